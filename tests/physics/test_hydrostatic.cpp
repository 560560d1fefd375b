// F1 of VALIDATION.md: a still tank stays still, with the hydrostatic pressure.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "physics_support.hpp"
#include "sluice/sim/probes.hpp"

namespace sluice {
namespace {

TEST(HydrostaticTank2D, PressureAndRestAfterTwoSeconds) {
  const io::CaseConfig config = testing::load_case("hydrostatic_2d.yaml");
  Simulation<2> sim(config);
  const double g = 9.81, rho0 = config.fluid.density, depth = 1.0;
  double worst_speed = 0;
  const auto& s = sim.state();
  testing::run_until(sim, 2.0, [&](const StepClock&) {
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      if (s.particles.is_fluid(i))
        worst_speed = std::max(worst_speed, s.particles.velocity[i].norm());
    }
  });
  ASSERT_NEAR(sim.time(), 2.0, 1e-12);

  // Bottom pressure: the fluid's pressure interpolated at the floor.
  io::ProbeConfig bottom;
  bottom.kind = io::ProbeKind::kPressure;
  bottom.point = Vec3(0.5, 0, 0);
  io::ProbeConfig level;
  level.kind = io::ProbeKind::kWaterHeight;
  level.point = Vec3(0.5, 0, 0);
  Probes probe({bottom, level}, "");
  const auto measured = probe.measure(sim.fluid());
  const double p_bottom = measured[0];
  EXPECT_NEAR(p_bottom, rho0 * g * depth, 0.03 * rho0 * g * depth);
  // The gauge finds the free surface within a particle spacing.
  EXPECT_NEAR(measured[1], depth, config.spacing);

  // Profile: L2 of the particle pressures against rho g (H - z), relative to rho g H.
  double error2 = 0, scale2 = 0;
  std::size_t outside = 0;
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    if (!s.particles.is_fluid(i)) continue;
    const auto& x = s.particles.position[i];
    const double expected = rho0 * g * (depth - x[1]);
    error2 += std::pow(s.particles.pressure[i] - expected, 2);
    scale2 += std::pow(rho0 * g * depth, 2);
    if (x[0] < 0 || x[0] > 1 || x[1] < 0) ++outside;
  }
  const double profile_error = std::sqrt(error2 / scale2);
  std::printf(
      "F1: bottom pressure %.5g Pa (rho g H %.5g, %+.2f %%), level %.4f m, profile error %.3f %%, "
      "largest speed %.4f m/s (bar %.4f)\n",
      p_bottom, rho0 * g * depth, 100 * (p_bottom / (rho0 * g * depth) - 1), measured[1],
      100 * profile_error, worst_speed, 0.01 * std::sqrt(g * depth));
  EXPECT_LT(profile_error, 0.03);
  EXPECT_EQ(outside, 0u);
  EXPECT_LT(worst_speed, 0.01 * std::sqrt(g * depth)) << "largest speed over the whole run";
}

}  // namespace
}  // namespace sluice
