// The fording vehicle of cases/fording.yaml on dry ground (issue 14): the chassis, carried on a
// prismatic joint by a prescribed carriage, keeps the set speed, and its wheels, turned only by
// their friction on the bed, roll without slipping.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "physics_support.hpp"
#include "reported_figure.hpp"
#include "sluice/io/csv_table.hpp"
#include "sluice/sim/runner.hpp"
#include "support/scratch_dir.hpp"

namespace sluice {
namespace {

using test_support::ScratchDir;

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
  testing::expect_figure({"vehicle chassis speed, the worst against the set one", "%", 3},
                         100 * worst_speed_error, testing::Bound::below, 0.5);
  for (int w = 0; w < 4; ++w) {
    const double rim_speed = wheel_rate_sum[w] / double(samples) * radius;
    std::printf("  wheel %d: omega r = %.6f m/s, %.3g %% off the chassis\n", w, rim_speed,
                100 * (rim_speed / chassis_speed - 1));
    EXPECT_NEAR(rim_speed, chassis_speed, 0.01 * chassis_speed) << "wheel " << w;
  }
}

// A box carried through water by a prescribed carriage on a vertical prismatic joint, as the
// fording chassis is: the velocity it keeps (which the fluid sees, and whose change the fluid
// takes for its acceleration) is the carriage's at every step, and the water drags it back. When
// the last half kick of a sub-step was left off the joints, WCSPH saw the box at 0.88 m/s while it
// moved at 1, and pushed it forward: a mean drag of -1439 N/m.
// The towed box: 0.24 m square, half under water 0.6 m deep, carried at 1 m/s after a 0.3 s
// ramp; the model by name.
io::CaseConfig towed_box(const std::string& model) {
  return io::parse_case(
      "dimension: 2\nspacing: 0.04\ndomain: {min: [0, 0], max: [3, 1.2]}\nend_time: 0.8\n"
      "output_interval: 0.8\nbody_interval: 0.01\nfluid:\n  blocks:\n"
      "    - {min: [0, 0], max: [3, 0.6]}\n"
      "walls:\n  - {type: tank, min: [0, 0], max: [3, 1.2], open: [z+]}\n"
      "bodies:\n"
      "  - {name: carriage, shape: sphere, radius: 0.05, density: 1000, position: [0.8, 1.0],\n"
      "     velocity: [1.0, 0], motion: prescribed,\n"
      "     prescribed: {type: constant_velocity, ramp_time: 0.3}}\n"
      "  - {name: box, shape: box, size: [0.24, 0.24], density: 500, position: [0.8, 0.6]}\n"
      "joints:\n"
      "  - {type: prismatic, bodies: [carriage, box], anchor: [0.8, 0.6], axis: [0, 0, 1]}\n"
      "model: {name: " +
          model + "}\n",
      "tow.yaml");
}

TEST(Vehicle, ABodyCarriedOnAJointMovesThroughWaterAtTheCarriagesVelocity) {
  const io::CaseConfig config = towed_box("wcsph");
  Simulation<2> sim(config);
  double worst = 0, drag = 0;
  long samples = 0;
  testing::run_until(sim, config.end_time, [&](const StepClock&) {
    const double carried = sim.bodies().state(1).velocity.x();
    const double carriage = sim.bodies().state(0).velocity.x();
    worst = std::max(worst, std::abs(carried - carriage));
    if (sim.time() > 0.4) {
      drag -= sim.coupler().fluid_force()[1].x();
      ++samples;
    }
  });
  drag /= double(samples);
  std::printf("carried box: velocity at most %.3g m/s off the carriage's; mean drag %.1f N/m\n",
              worst, drag);
  EXPECT_LT(worst, 1e-3);
  EXPECT_GT(drag, 0);
}

// The grid's projection solves the carried box's velocity with the pressure (the projection
// scheme): through the joint's mobility, the box keeps the carriage's velocity at every step.
// Solved with the box's own mobility alone, the drag's impulse would slow it by dt F / m (about 0.1
// m/s a step here), which the joint would then have to take back.
TEST(Vehicle, TheGridsProjectionKeepsTheJointsOfTheBodiesItMoves) {
  io::CaseConfig config = towed_box("mac");
  config.coupling.scheme = "projection";
  Simulation<2> sim(config);
  ASSERT_STREQ(sim.coupler().scheme().name(), "projection");
  double worst = 0, drag = 0;
  long samples = 0;
  testing::run_until(sim, config.end_time, [&](const StepClock&) {
    worst = std::max(
        worst, std::abs(sim.bodies().state(1).velocity.x() - sim.bodies().state(0).velocity.x()));
    if (sim.time() > 0.4) {
      drag -= sim.coupler().fluid_force()[1].x();
      ++samples;
    }
  });
  drag /= double(samples);
  std::printf(
      "carried box (mac, projection): velocity at most %.3g m/s off the carriage's; mean "
      "drag %.1f N/m\n",
      worst, drag);
  EXPECT_LT(worst, 1e-3);
  EXPECT_GT(drag, 0);
}

// loads.csv's rows are the mean loads over their intervals. The step that lands on a row's time
// is shortened, and a constraint fluid's drag over such a step is far from its drag over the
// others (on the fording vehicle near 0 N against 200-500 N): written as it stood at the row's
// time, the towed box's mean drag read 278 N/m against 340 N/m over every step. The mean of the
// rows over 0.4-0.8 s must match the time-weighted mean over every step of an unwritten run
// that lands its steps on the rows' times as the written run does, and so takes the same
// steps, within 0.5 %. (Runs whose steps land elsewhere are other samples of the flow: the
// written run's mean drag over 0.4-0.8 s spans 332-357 N/m for rows every 0.005-0.025 s.)
TEST(Vehicle, LoadRowsAreMeansOverTheirIntervals) {
  const io::CaseConfig config = towed_box("constraint");
  ScratchDir scratch("loads");
  RunOptions options;
  options.quiet = true;
  options.out_dir = scratch.path().string();
  run_case(config, options);
  const io::CsvTable loads = io::read_csv_table(options.out_dir + "/loads.csv");
  const std::vector<double> time = loads.values(0);
  const std::vector<double> drag = loads.values(*loads.column("box_drag"));
  double rows = 0;
  long count = 0;
  for (std::size_t k = 0; k < time.size(); ++k) {
    if (time[k] > 0.4 + 1e-9) {
      rows += drag[k];
      ++count;
    }
  }
  rows /= double(count);

  Simulation<2> sim(config);
  double impulse = 0, span = 0, before = 0;
  for (int row = 1; row <= static_cast<int>(std::lround(config.end_time / config.body_interval));
       ++row) {
    testing::run_until(sim, row * config.body_interval, [&](const StepClock&) {
      const double dt = sim.time() - before;
      before = sim.time();
      if (sim.time() <= 0.4 + 1e-9) return;
      impulse -= dt * sim.coupler().fluid_force()[1].x();
      span += dt;
    });
  }
  const double every_step = impulse / span;
  std::printf(
      "towed box (constraint): mean drag of loads.csv's rows %.1f N/m, over every step "
      "%.1f N/m (%+.2f %%)\n",
      rows, every_step, 100 * (rows / every_step - 1));
  testing::expect_figure({"towed box's drag, loads.csv's rows against every step", "%", 2},
                         100 * (rows / every_step - 1), testing::Bound::within, 0.5);
}

}  // namespace
}  // namespace sluice
