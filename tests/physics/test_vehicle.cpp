// The fording vehicle of cases/fording.yaml on dry ground (issue 14): the chassis, carried on a
// prismatic joint by a prescribed carriage, keeps the set speed, and its wheels, turned only by
// their friction on the bed, roll without slipping.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "physics_support.hpp"

namespace sluice {
namespace {

TEST(Vehicle, KeepsItsSpeedAndItsWheelsRollOnDryGround) {
  io::CaseConfig config = testing::load_case("fording.yaml");
  config.fluid.blocks.clear();  // dry ground: a case of bodies alone
  const double set_speed = config.bodies[0].velocity.x();
  const double radius = config.bodies[2].radius;
  Simulation<3> sim(config);
  // After the carriage's 0.3 s ramp and the wheels' spin-up from rest (about 0.15 s).
  const double from = 0.6, end = 1.2;
  double worst_speed_error = 0, chassis_speed_sum = 0;
  double wheel_rate_sum[4] = {0, 0, 0, 0};
  long samples = 0;
  testing::run_until(sim, end, [&](const StepClock&) {
    if (sim.time() < from) return;
    const double v = sim.bodies().state(1).velocity.x();
    worst_speed_error = std::max(worst_speed_error, std::abs(v - set_speed) / set_speed);
    chassis_speed_sum += v;
    for (int w = 0; w < 4; ++w)
      wheel_rate_sum[w] += sim.bodies().state(2 + w).angular_velocity().y();
    ++samples;
  });
  ASSERT_GT(samples, 100);
  const double chassis_speed = chassis_speed_sum / double(samples);
  std::printf("vehicle: chassis speed %.6f m/s (set %.3g), worst %.3g %% off\n", chassis_speed,
              set_speed, 100 * worst_speed_error);
  EXPECT_LT(worst_speed_error, 0.005);
  for (int w = 0; w < 4; ++w) {
    const double rim_speed = wheel_rate_sum[w] / double(samples) * radius;
    std::printf("  wheel %d: omega r = %.6f m/s, %.3g %% off the chassis\n", w, rim_speed,
                100 * (rim_speed / chassis_speed - 1));
    EXPECT_NEAR(rim_speed, chassis_speed, 0.01 * chassis_speed) << "wheel " << w;
  }
}

}  // namespace
}  // namespace sluice
