// Open boundaries for the particle models: an open channel (cases/open_channel_2d.yaml), water
// 0.3 m deep entering a 3 m flume at 0.3 m/s through an inlet's buffer and leaving by an outlet
// hydrostatic below the same depth, over a free-slip bed. Issue 43's bars: once steady, the flux
// out equals the flux in within 1 % over 10 s, and the depth stays within 2 % of its target.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "physics_support.hpp"
#include "reported_figure.hpp"
#include "sluice/fluid/particle_fluid.hpp"

namespace sluice {
namespace {

using testing::load_case;
using testing::run_until;

constexpr double kDepth = 0.3;        // the inlet's and the outlet's
constexpr double kInflowSpeed = 0.3;  // the inlet's [m/s]

// The water's mean depth over x in [lo, hi]: in each column a spacing wide, the highest fluid
// particle's height above the floor plus half a spacing (its own extent), averaged over the
// columns. (The water-height probe reads a gauge in quarter spacings; wcsph's volumes m / rho
// give the same depth to 0.2 %, but mps keeps no volume of its own: its density is rho0.)
double mean_depth(const ParticleFluid<2>& fluid, double lo, double hi) {
  const auto& s = fluid.state();
  const auto& ps = s.particles;
  const double dx = s.spacing;
  const auto columns = static_cast<std::size_t>(std::lround((hi - lo) / dx));
  std::vector<double> top(columns, s.domain.min[2] - 0.5 * dx);
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const double x = ps.position[i][0];
    if (!ps.is_fluid(i) || x < lo || x >= hi) continue;
    const auto c = std::min(columns - 1, static_cast<std::size_t>((x - lo) / dx));
    top[c] = std::max(top[c], double(ps.position[i][1]));
  }
  double sum = 0;
  for (const double z : top) sum += z + 0.5 * dx - s.domain.min[2];
  return sum / static_cast<double>(columns);
}

struct ChannelFigures {
  double flux_in = 0, flux_out = 0;  // [m^2/s]
  double depth = 0;                  // the mean depth [m]
  double worst_window = 0;           // the largest departure of a half second's mean depth
};

// The case with `overrides` to `end`, measured from `from`: the fluxes are the flux probes'
// readings at each step, time-weighted; the depth the mean over the middle 2.4 m.
ChannelFigures run_channel(const std::vector<std::string>& overrides, double end, double from) {
  Simulation<2> sim(load_case("open_channel_2d.yaml", overrides));
  const auto& fluid = dynamic_cast<const ParticleFluid<2>&>(sim.fluid());
  const double window = 0.5;
  ChannelFigures f;
  double span = 0, window_depth = 0, window_span = 0;
  run_until(sim, end, [&](const StepClock& c) {
    if (c.time <= from) return;
    const double d = mean_depth(fluid, 0.3, 2.7);
    f.flux_in -= c.dt * fluid.boundary_flux(0);
    f.flux_out += c.dt * fluid.boundary_flux(1);
    f.depth += c.dt * d;
    span += c.dt;
    window_depth += c.dt * d;
    window_span += c.dt;
    if (window_span >= window * (1 - 1e-9)) {
      const double departure = window_depth / window_span / kDepth - 1;
      if (std::abs(departure) > std::abs(f.worst_window)) f.worst_window = departure;
      window_depth = window_span = 0;
    }
  });
  f.flux_in /= span;
  f.flux_out /= span;
  f.depth /= span;
  std::printf(
      "open channel: flux in %.6f, out %.6f m^2/s; depth %.5f m, worst half-second mean "
      "%+.3f %%\n",
      f.flux_in, f.flux_out, f.depth, 100 * f.worst_window);
  return f;
}

// wcsph at 0.02 m (15 particles over the depth) to 12 s, measured over the last 10 (the water
// starts at the inflow's speed, so the flow is steady from the first steps). Measured (release
// and baseline builds, 1 and 2 threads alike to five digits): flux out 0.32 % above the flux
// in, mean depth 0.50 % below 0.3 m, the worst half second 0.86 % below.
TEST(OpenChannel, WcsphCarriesTheInflowToTheOutletAtItsDepth) {
  const ChannelFigures f = run_channel({}, 12, 2);
  testing::expect_figure({"open channel `wcsph` (0.02 m): flux out from flux in", "%", 2},
                         100 * (f.flux_out / f.flux_in - 1), testing::Bound::within, 1);
  testing::expect_figure({"open channel `wcsph` (0.02 m): mean depth from its target", "%", 2},
                         100 * (f.depth / kDepth - 1), testing::Bound::within, 2);
  testing::expect_figure(
      {"open channel `wcsph` (0.02 m): worst half-second depth from its target", "%", 2},
      100 * f.worst_window, testing::Bound::within, 2);
}

// mps at 0.02 m to 20 s, measured over the last 10: its start (the water set out at the lattice's
// spacing and hydrostatic pressure, which mps's pressure equation does not hold exactly) swings
// the outflow by 8 % for the first 10 s, and its water is still settling after it: its depth is
// a limit, 2.9 % below 0.3 m (baseline build 3.1 %), the worst half second 3.3 % below (3.6 %),
// as its surface particles settle closer than the lattice they came in on (the still tank's F1
// water settles 0.7 % so). The flux out from the flux in over those 10 s carries the settling
// water's change of volume, which the builds' rounding moves: -0.07 % (baseline +0.95 %), within
// the 1 % bar but by less than three times that spread, so it is a limit too. What is held: the
// inlet supplies its flux, 0.3 m/s over 0.3 m (-0.013 %, baseline -0.011 %; bar 0.5 % as in 3D).
TEST(OpenChannel, MpsCarriesTheInflowToTheOutlet) {
  const ChannelFigures f = run_channel({"model={name: mps}"}, 20, 10);
  testing::expect_figure({"open channel `mps` (0.02 m): flux in from the inlet's", "%", 3},
                         100 * (f.flux_in / (kInflowSpeed * kDepth) - 1), testing::Bound::within,
                         0.5);
  testing::report_limit({"open channel `mps` (0.02 m): flux out from flux in", "%", 2},
                        100 * (f.flux_out / f.flux_in - 1), testing::Bound::within, 1);
  testing::report_limit({"open channel `mps` (0.02 m): mean depth from its target", "%", 2},
                        100 * (f.depth / kDepth - 1), testing::Bound::within, 2);
  testing::report_limit(
      {"open channel `mps` (0.02 m): worst half-second depth from its target", "%", 2},
      100 * f.worst_window, testing::Bound::within, 2);
}

// The buffers in 3D (cases/open_channel_3d.yaml, wcsph at 0.05 m): a parabolic inlet across the
// width (10 rows of particles) and the depth (6) carries the parabola's mean over its rows,
// 0.3 m/s x 0.5 m x 0.3 m x (1 + 1/(2 10^2)) (1 + 1/(2 6^2)), through its inner face. Measured
// over 0.5-2 s, the probe read at each step: 0.015 % below (bar 0.5 %: the face's reading
// ripples by a few percent as rows cross it).
TEST(OpenChannel, ParabolicInletIn3DCarriesItsMeanSpeedOverItsRows) {
  Simulation<3> sim(load_case("open_channel_3d.yaml"));
  const double in = testing::mean_inflow(sim, 0, 0.5, 2.0);
  const double expected = 0.3 * 0.5 * 0.3 * (1 + 1 / 200.0) * (1 + 1 / 72.0);
  std::printf("3D parabolic inlet: flux in %.6f m^3/s, its rows' mean %.6f\n", in, expected);
  testing::expect_figure({"open channel 3D `wcsph` (0.05 m): inflow from its rows' mean", "%", 3},
                         100 * (in / expected - 1), testing::Bound::within, 0.5);
}

}  // namespace
}  // namespace sluice
