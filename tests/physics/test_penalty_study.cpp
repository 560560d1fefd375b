// Seed 002's stiffness / spacing-ratio study at CI size (B4 of VALIDATION.md): a sheet of 81
// fluid particles 3.3 mm apart strikes a layer of solid particles at 2.43 m/s (a fall of
// 0.3 m) in a 0.03 m wide tank, for solid spacings of 0.61, 1.5 and 4.9 fluid spacings and
// Ks from 1 to 10^4 N/m. Expected: the share held back never falls as Ks grows; a larger
// spacing ratio needs a larger Ks to hold everything back (at 4.9 the pores between the solid
// particles are wider than a fluid particle and no Ks does); the fluid's mass stays exact;
// and the impact, resolved in sub-steps, peaks at a force that grows as sqrt(Ks) (a spring
// of stiffness Ks, with its critical dashpot, stops a mass m arriving at v with a force
// proportional to v sqrt(m Ks)): measured slope 0.501 of log F against log Ks over 1e4-1e6.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "physics_support.hpp"
#include "reported_figure.hpp"

namespace sluice {
namespace {

constexpr double kSpacing = 0.0033;

struct Outcome {
  double held_back = 0;
  double peak_force = 0;
  double mass_change = 0;
};

Outcome strike(double ratio, double stiffness) {
  const std::string text = fmt::format(R"(
name: penalty_study
dimension: 3
spacing: {0}
domain: {{min: [0, 0, 0], max: [0.0297, 0.0297, 0.1]}}
end_time: 0.1
output_interval: 0.1
fluid:
  density: 998.29
  viscosity: 1.0e-6
  blocks:
    - {{min: [0, 0, 0.06], max: [0.0297, 0.0297, 0.0633], velocity: [0, 0, -2.43]}}
walls:
  - {{type: tank, min: [0, 0, 0], max: [0.0297, 0.0297, 0.1], open: [z+]}}
model:
  name: penalty-sph
  gas_stiffness: 1.0e-5
  surface_tension: 0
  wall_friction: 0.1
  Ks: {1}
  time_step: 0.01
  solids:
    - {{min: [0, 0, 0.03], max: [0.0297, 0.0297, {2}], spacing_ratio: {3}}}
)",
                                       kSpacing, stiffness, 0.03 + 1.5 * ratio * kSpacing, ratio);
  Simulation<3> sim(io::parse_case(text, "penalty_study.yaml"));
  const double mass = sim.fluid().observation().energy().mass;
  testing::run_until(sim, 0.1, [](const StepClock&) {});
  Outcome out;
  for (const auto& [name, value] : sim.fluid().observation().counters()) {
    if (name == "held_back_fraction") out.held_back = value;
    if (name == "peak_boundary_force") out.peak_force = value;
  }
  out.mass_change = sim.fluid().observation().energy().mass - mass;
  return out;
}

TEST(PenaltyStudy, StiffnessAndSpacingRatioTrends) {
  const std::vector<double> stiffnesses = {1, 10, 100, 1e3, 1e4};
  const std::vector<double> ratios = {0.61, 1.5, 4.9};
  std::map<double, double> smallest_holding;  // ratio -> smallest Ks holding all (inf: none)
  for (const double ratio : ratios) {
    double previous = -1;
    smallest_holding[ratio] = INFINITY;
    for (const double ks : stiffnesses) {
      const Outcome o = strike(ratio, ks);
      SCOPED_TRACE(fmt::format("ratio {}, Ks {}: held back {}", ratio, ks, o.held_back));
      EXPECT_EQ(o.mass_change, 0);
      EXPECT_GE(o.held_back, previous);
      previous = o.held_back;
      if (o.held_back == 1 && std::isinf(smallest_holding[ratio])) smallest_holding[ratio] = ks;
    }
  }
  EXPECT_LE(smallest_holding[0.61], smallest_holding[1.5]);
  EXPECT_LT(smallest_holding[1.5], smallest_holding[4.9]);
  EXPECT_LT(smallest_holding[0.61], 1e4);
}

TEST(PenaltyStudy, ImpactForceGrowsAsTheSquareRootOfTheStiffness) {
  // Least squares of log F against log Ks over two decades where every particle is held.
  const std::vector<double> stiffnesses = {1e4, 1e5, 1e6};
  double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
  for (const double ks : stiffnesses) {
    const Outcome o = strike(0.61, ks);
    ASSERT_EQ(o.held_back, 1) << ks;
    const double x = std::log(ks), y = std::log(o.peak_force);
    sx += x, sy += y, sxx += x * x, sxy += x * y, syy += y * y;
  }
  const double n = static_cast<double>(stiffnesses.size());
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  const double r = (n * sxy - sx * sy) / std::sqrt((n * sxx - sx * sx) * (n * syy - sy * sy));
  testing::expect_figure({"B4 peak force against log Ks, slope - 0.5", "", 3}, slope - 0.5,
                         testing::Bound::within, 0.1);
  testing::expect_figure({"B4 peak force against log Ks, R^2", "", 5}, r * r, testing::Bound::above,
                         0.95);
}

// The bodies feel the reaction of the boundary forces the fluid felt in its sub-steps: water
// resting on a fixed box that spans the tank presses on it with its weight.
TEST(PenaltySphBodies, WaterRestingOnABoxPressesWithItsWeight) {
  const std::string text = R"(
name: water_on_a_box
dimension: 2
spacing: 0.005
domain: {min: [0, 0], max: [0.2, 0.2]}
end_time: 1.0
output_interval: 1.0
fluid:
  blocks:
    - {min: [0, 0.08], max: [0.2, 0.11]}
walls:
  - {type: tank, min: [0, 0], max: [0.2, 0.2], open: [z+]}
bodies:
  - {name: box, shape: box, size: [0.2, 0.04], density: 2000, position: [0.1, 0.05],
     motion: fixed}
model:
  name: penalty-sph
  surface_tension: 0
)";
  Simulation<2> sim(io::parse_case(text, "water_on_a_box.yaml"));
  const double weight = sim.fluid().observation().energy().mass * 9.81;
  double sum = 0;
  long samples = 0;
  testing::run_until(sim, 1.0, [&](const StepClock& c) {
    if (c.time <= 0.8) return;
    sum += sim.coupler().fluid_force()[0].z();
    ++samples;
  });
  ASSERT_GT(samples, 10);
  const double mean = sum / samples;
  std::printf("water on a box: mean load %.4g N/m over 0.8-1.0 s, weight %.4g N/m (%+.2f %%)\n",
              mean, weight, 100 * (-mean / weight - 1));
  EXPECT_NEAR(-mean, weight, 0.05 * weight);
}

}  // namespace
}  // namespace sluice
