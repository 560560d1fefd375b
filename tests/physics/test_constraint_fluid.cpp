// The constraint-fluid model (issue 12; seed 001's second method): one density constraint per
// particle, solved with the bodies in one complementarity problem.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "particle_state_of.hpp"
#include "physics_support.hpp"
#include "reported_figure.hpp"
#include "sluice/fluid/constraint/constraint_model.hpp"
#include "sluice/fluid/wcsph/wcsph_parameters.hpp"

namespace sluice {
namespace {

using testing::load_case;
using testing::run_until;

template <int D>
const ConstraintModel<D>& constraint_model(const Simulation<D>& sim) {
  return dynamic_cast<const ConstraintModel<D>&>(sim.fluid());
}

// Fluid particles, and those outside the tank [0, 1] x [0, inf).
std::pair<std::size_t, std::size_t> fluid_and_outside(const ParticleSet<2>& ps, double width) {
  std::size_t fluid = 0, outside = 0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (!ps.is_fluid(i)) continue;
    ++fluid;
    if (ps.position[i][0] < 0 || ps.position[i][0] > width || ps.position[i][1] < 0) ++outside;
  }
  return {fluid, outside};
}

// The still tank's depth, a measure of compression independent of the constraint model's own
// density sums: the mean over the columns x in [0.2, 0.8] m (one spacing wide) of the highest
// fluid particle's height plus half a spacing. still_depth averages it over every step from 1.5
// to 2 s.
double mean_surface_height(const ParticleSet<2>& ps, double dx) {
  const int columns = static_cast<int>(std::lround(0.6 / dx));
  std::vector<double> top(static_cast<std::size_t>(columns), -1.0);
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (!ps.is_fluid(i)) continue;
    const int c = static_cast<int>(std::floor((ps.position[i][0] - 0.2) / dx));
    if (c >= 0 && c < columns)
      top[std::size_t(c)] = std::max(top[std::size_t(c)], ps.position[i][1]);
  }
  double sum = 0;
  for (double z : top) sum += z;
  return sum / columns + dx / 2;
}

double still_depth(const io::CaseConfig& config) {
  Simulation<2> sim(config);
  double sum = 0;
  long samples = 0;
  run_until(sim, 2.0, [&](const StepClock& c) {
    if (c.time <= 1.5) return;
    sum += mean_surface_height(testing::particle_state(sim).particles, config.spacing);
    ++samples;
  });
  return sum / double(samples);
}

// F1's tank is 1 m deep. The depth measure's own error, on WCSPH, whose compression its
// equation of state fixes: its mean rho / rho0 - 1 over the column is g H / (2 c0^2), so its water
// stands that fraction below 1 m.
double depth_measure_error(const std::string& spacing) {
  const io::CaseConfig wcsph = load_case("hydrostatic_2d.yaml", {spacing});
  const double g = 9.81, depth = 1.0, c0 = read_wcsph_parameters(wcsph).sound_speed;
  return std::abs(still_depth(wcsph) - depth * (1 - g * depth / (2 * c0 * c0))) / depth;
}

// The bar on the constraint fluid's compression by the depth: 2 %, nearly eight times the measure's
// error (0.25-0.26 % at 0.05 and 0.025 m). The model's own bar, 1 % on the kernel-summed density,
// is not met by this measure at 0.05 m (docs/validation.md, constraint fluids).
constexpr double kDepthCompressionBar = 0.02;

void check_depth(double dx, double constraint_depth, double measure_error) {
  const double compression = 1 - constraint_depth;
  std::printf(
      "F1 depth at dx %.3g m: the measure reads wcsph %.3f %% off its equation of state; "
      "constraint %.5f m, compression %+.3f %%\n",
      dx, 100 * measure_error, constraint_depth, 100 * compression);
  const std::string at = fmt::format(", {} m", dx);
  testing::expect_figure({"depth measure's error on `wcsph`" + at, "%", 3}, 100 * measure_error,
                         testing::Bound::below, 100 * kDepthCompressionBar / 3);
  testing::expect_figure({"`constraint` depth compression" + at, "%", 3}, 100 * compression,
                         testing::Bound::within, 100 * kDepthCompressionBar);
}

// F1: the pressure the constraint impulses give at the floor (dx gamma / (h V), the probe's
// Shepard average of it at nine points along the floor, x = 0.1 ... 0.9 m) is rho g H within
// 3 %, as a mean over 1.5-2 s: each particle's pressure is noisy (the impulses of a constraint
// fluid answer every small rearrangement), their mean is not. The water stays in the tank and
// keeps every particle; its largest speed is reported. Its depth over 1.5-2 s is the
// compression's independent measure (check_depth).
TEST(ConstraintFluid, HydrostaticBottomPressure) {
  const io::CaseConfig config = load_case("hydrostatic_2d.yaml", {"model.name=constraint"});
  Simulation<2> sim(config);
  const double g = 9.81, rho0 = config.fluid.density, depth = 1.0, expected = rho0 * g * depth;
  const std::size_t fluid = testing::particle_state(sim).fluid_count;
  double sum = 0, fastest = 0, surface = 0;
  long samples = 0;
  run_until(sim, 2.0, [&](const StepClock& c) {
    if (c.time <= 1.5) return;
    for (int k = 1; k <= 9; ++k)
      sum += sim.fluid().observation().pressure_at(Vec3(0.1 * k, 0, 0)) / 9;
    surface += mean_surface_height(testing::particle_state(sim).particles, config.spacing);
    ++samples;
    const auto& ps = testing::particle_state(sim).particles;
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (ps.is_fluid(i)) fastest = std::max(fastest, ps.velocity[i].norm());
    }
  });
  ASSERT_GT(samples, 10);
  const double mean = sum / double(samples);
  const auto [fluid_now, outside] = fluid_and_outside(testing::particle_state(sim).particles, 1.0);
  std::printf(
      "F1 (constraint): bottom pressure over 1.5-2 s %.5g Pa (rho g H %.5g, %+.2f %%) over %ld "
      "steps; largest speed over 1.5-2 s %.4f m/s (%.4f sqrt(gH)); largest density error %.4f %%\n",
      mean, expected, 100 * (mean / expected - 1), samples, fastest, fastest / std::sqrt(g * depth),
      100 * constraint_model(sim).largest_density_error());
  testing::expect_figure({"F1 `constraint` bottom pressure against rho g H", "%", 2},
                         100 * (mean / expected - 1), testing::Bound::within, 3);
  EXPECT_EQ(fluid_now, fluid);
  EXPECT_EQ(outside, 0u);
  check_depth(config.spacing, surface / double(samples), depth_measure_error("spacing=0.025"));
}

// F1's still-tank depth at 0.05 m (at 0.025 m: HydrostaticBottomPressure).
TEST(ConstraintFluid, StillTankDepthAtTwiceTheSpacing) {
  const double depth =
      still_depth(load_case("hydrostatic_2d.yaml", {"spacing=0.05", "model.name=constraint"}));
  check_depth(0.05, depth, depth_measure_error("spacing=0.05"));
}

// The paper's main claim: incompressible at large steps. F2 to 0.7 s at 0.05 m with the
// constraint model's own step (its default cfl) against WCSPH's at the same spacing: the mean
// step is at least five times WCSPH's, and no fluid particle is ever compressed by 1 % or more
// (the largest rho / rho_ref - 1 over every particle and step). The particle count holds.
TEST(ConstraintFluid, DensityErrorAtFiveTimesTheWcsphStep) {
  auto mean_step = [](Simulation<2>& sim) {
    long steps = 0;
    run_until(sim, 0.7, [&](const StepClock&) { ++steps; });
    return sim.time() / double(steps);
  };
  Simulation<2> wcsph(load_case("dam_break_2d.yaml", {"spacing=0.05"}));
  const double wcsph_step = mean_step(wcsph);
  Simulation<2> sim(load_case("dam_break_2d.yaml", {"model.name=constraint", "spacing=0.05"}));
  const std::size_t fluid = testing::particle_state(sim).fluid_count;
  const double step = mean_step(sim);
  const double error = constraint_model(sim).largest_density_error();
  std::printf(
      "F2 (constraint): mean step %.3g s against WCSPH's %.3g s (%.1f times); largest density "
      "error %.3f %%\n",
      step, wcsph_step, step / wcsph_step, 100 * error);
  testing::expect_figure({"F2 `constraint` mean step / `wcsph`'s", "", 1}, step / wcsph_step,
                         testing::Bound::above, 5);
  testing::expect_figure({"F2 `constraint` largest density error", "%", 3}, 100 * error,
                         testing::Bound::below, 1);
  EXPECT_EQ(fluid_and_outside(testing::particle_state(sim).particles, 4.0).first, fluid);
}

// Same answer on one and two threads, bit for bit: every row is built and every particle's
// velocity change gathered by one thread, the solver's dot products sum in fixed blocks.
TEST(ConstraintFluid, SameOnOneAndTwoThreads) {
  const auto [one, two] = testing::on_one_and_two_threads([] {
    Simulation<2> sim(load_case("dam_break_2d.yaml", {"model.name=constraint", "spacing=0.05"}));
    run_until(sim, 0.2, [](const StepClock&) {});
    return testing::particle_state(sim).particles;
  });
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    ASSERT_EQ(one.position[i], two.position[i]) << i;
    ASSERT_EQ(one.velocity[i], two.velocity[i]) << i;
    ASSERT_EQ(one.pressure[i], two.pressure[i]) << i;
  }
}

}  // namespace
}  // namespace sluice
