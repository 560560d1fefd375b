// Free solid particles of the penalty-sph model (seed 002's granular bed as rigid bodies): the
// fluid and the grains exchange the boundary forces both ways, in pieces of the fluid's step
// short enough for the grains on their stiff springs (Coupler::exchanges).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "particle_state_of.hpp"
#include "physics_support.hpp"

namespace sluice {
namespace {

// Water at rest on a bed of free discs: the discs carry the water's weight, and the floor
// carries the discs and the water. Means over the last second of cases/free_bed_2d.yaml. (The
// tank's side walls take a little of the water's weight where it rests in their corners:
// measured -0.9 % on the discs.)
TEST(PenaltySphFreeGrains, BedCarriesTheWaterAndTheFloorCarriesBoth) {
  Simulation<2> sim(testing::load_case("free_bed_2d.yaml"));
  const std::size_t grains = sim.bodies().count();
  ASSERT_EQ(grains, 20u);
  double bed_weight = 0;
  for (std::size_t b = 0; b < grains; ++b) bed_weight += sim.bodies().state(b).mass * 9.81;
  const double water_weight = sim.fluid().observation().energy().mass * 9.81;
  double fluid_load = 0, floor_load = 0;
  long samples = 0;
  testing::run_until(sim, 2.0, [&](const StepClock& c) {
    if (c.time <= 1.0) return;
    for (std::size_t b = 0; b < grains; ++b) {
      fluid_load += sim.coupler().fluid_force()[b].z();
      floor_load += sim.bodies().system().contact_force()[b].z();
    }
    ++samples;
  });
  ASSERT_GT(samples, 100);
  fluid_load /= double(samples);
  floor_load /= double(samples);
  std::printf(
      "free bed: water on the discs %.4g N/m (weight %.4g, %+.2f %%), floor under the discs "
      "%.4g N/m (discs and water %.4g, %+.2f %%)\n",
      -fluid_load, water_weight, 100 * (-fluid_load / water_weight - 1), floor_load,
      bed_weight + water_weight, 100 * (floor_load / (bed_weight + water_weight) - 1));
  EXPECT_NEAR(-fluid_load, water_weight, 0.03 * water_weight);
  EXPECT_NEAR(floor_load, bed_weight + water_weight, 0.03 * (bed_weight + water_weight));
  for (const auto& [name, value] : sim.fluid().observation().counters()) {
    if (name == "held_back_fraction") {
      EXPECT_EQ(value, 1);
    }
  }
}

// A block of water thrown at one free grain without gravity or walls: whatever the springs
// do, the momentum the water loses the grain gains, exchange by exchange.
TEST(PenaltySphFreeGrains, WaterStrikingAGrainKeepsTheMomentum) {
  const std::string text = R"(
name: strike_a_grain
dimension: 3
spacing: 0.0033
domain: {min: [-0.05, -0.05, -0.05], max: [0.05, 0.05, 0.05]}
gravity: [0, 0, 0]
end_time: 0.06
output_interval: 0.06
fluid:
  density: 998.29
  viscosity: 1.0e-6
  blocks:
    - {min: [-0.0066, -0.0066, 0.01], max: [0.0066, 0.0066, 0.0232], velocity: [0, 0, -1]}
model:
  name: penalty-sph
  max_speed: 1
  surface_tension: 0
  Ks: 5.0e4
  time_step: 0.005
  solids:
    - {min: [-0.005, -0.005, -0.005], max: [0.005, 0.005, 0.005], spacing_ratio: 3.0303,
       free: true}
)";
  Simulation<3> sim(io::parse_case(text, "strike_a_grain.yaml"));
  ASSERT_EQ(sim.bodies().count(), 1u);
  auto momentum = [&] {
    Vec3 p = sim.bodies().state(0).mass * sim.bodies().state(0).velocity;
    const auto& ps = testing::particle_state(sim).particles;
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (ps.is_fluid(i)) p += ps.mass[i] * ps.velocity[i];
    }
    return p;
  };
  const Vec3 start = momentum();
  testing::run_until(sim, 0.06, [](const StepClock&) {});
  const Vec3 end = momentum();
  const double grain_speed = sim.bodies().state(0).velocity.z();
  std::printf("grain struck: %.4g m/s down; momentum %.6g -> %.6g kg m/s (grain %.4g)\n",
              -grain_speed, start.z(), end.z(), sim.bodies().state(0).mass * grain_speed);
  EXPECT_LT(grain_speed, -0.01);  // the water did push it
  EXPECT_LT((end - start).norm(), 1e-9 * start.norm());
}

}  // namespace
}  // namespace sluice
