// Open boundaries against a published answer: flow past a cylinder in a channel, Schäfer &
// Turek's (1996) benchmark 2D-1 (Re = 20, steady), between a parabolic inlet and a pressure
// outlet: cases/cylinder_channel_2d.yaml with the grid model, cases/cylinder_channel_wcsph_2d.yaml
// with weakly compressible SPH and its transport velocity. validation/cylinder_channel.py runs
// the finer grids and draws the coefficients' convergence (docs/validation.md, F7).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "physics_support.hpp"
#include "reported_figure.hpp"
#include "sluice/linear/hypre_session.hpp"

namespace sluice {
namespace {

using testing::load_case;
using testing::run_until;

// Schäfer & Turek's ranges, and the scales of their coefficients: 2 F / (rho U^2 D).
constexpr double kDragMiddle = 0.5 * (5.57 + 5.59);
constexpr double kLiftMiddle = 0.5 * (0.0104 + 0.0110);
constexpr double kPressureDropMiddle = 0.5 * (0.1172 + 0.1176);
constexpr double kCoefficientPerNewton = 2 / (1.0 * 0.2 * 0.2 * 0.1);

// 2D-1's figures, each a mean over the span from `from` to `end`: C_D, C_L and the pressure
// drop from the cylinder's front point to its back point (x = 0.15 and 0.25 m).
struct Benchmark2D1 {
  double drag = 0, lift = 0, drop = 0;
};

Benchmark2D1 run_2d1(Simulation<2>& sim, double end, double from, const char* label) {
  const FluidObservation& fluid = sim.fluid().observation();
  Benchmark2D1 b;
  double span = 0;
  run_until(sim, end, [&](const StepClock& c) {
    if (c.time <= from) return;
    b.drag += c.dt * sim.coupler().fluid_force()[0].x();
    b.lift += c.dt * sim.coupler().fluid_force()[0].z();
    b.drop +=
        c.dt * (fluid.pressure_at(Vec3(0.15, 0, 0.2)) - fluid.pressure_at(Vec3(0.25, 0, 0.2)));
    span += c.dt;
  });
  b.drag *= kCoefficientPerNewton / span;
  b.lift *= kCoefficientPerNewton / span;
  b.drop /= span;
  std::printf(
      "2D-1 %s at 0.005 m: C_D %.4f (5.57-5.59), C_L %.5f (0.0104-0.0110), dp %.5f Pa "
      "(0.1172-0.1176)\n",
      label, b.drag, b.lift, b.drop);
  return b;
}

// 2D-1 at 0.005 m cells (20 across the cylinder) to 4 s, where the drag has settled to 0.01 %
// a second: its drag coefficient, the mean of the last 0.5 s, within 5 % of the range's middle
// (measured 4.8 % above it; 6.3 % above at 0.01 m cells), the pressure drop across the cylinder
// within 2 % (measured 0.08 %; both pressures means over the same 0.5 s, for a step's pressure
// varies from the next by a percent); the lift, the difference of two nearly equal pressures on a
// staircase of cut cells, is reported (40 % below, and not steady to its second digit).
TEST(OpenBoundaries, CylinderInAChannelMeetsSchaeferTurek2D1) {
  // The case's solver is hypre's: the process's session, started at its first solve and
  // stopped when the process ends.
  static HypreSession hypre;
  ModelServices services;
  services.hypre = &hypre;
  Simulation<2> sim(load_case("cylinder_channel_2d.yaml", {"spacing=0.005"}), services);
  const Benchmark2D1 b = run_2d1(sim, 4.0, 3.5, "mac");
  testing::expect_figure({"2D-1 `mac` (0.005 m) C_D from the range's middle", "%", 2},
                         100 * (b.drag / kDragMiddle - 1), testing::Bound::within, 5);
  testing::expect_figure({"2D-1 `mac` (0.005 m) pressure drop from the range's middle", "%", 2},
                         100 * (b.drop / kPressureDropMiddle - 1), testing::Bound::within, 2);
  testing::report_limit({"2D-1 `mac` (0.005 m) C_L from the range's middle", "%", 1},
                        100 * (b.lift / kLiftMiddle - 1), testing::Bound::within, 5);
}

// 2D-1 with `wcsph` at 0.005 m (20 particles across the cylinder), the inflow ramped up over
// 4 s, to 7 s: the drag coefficient, the mean of the last second, within 5 % of the range's
// middle (measured +3.3 %; +5.7 % at 0.01 m, so the error falls with the spacing). The pressure
// drop across the cylinder (+2.7 %) is reported against the grid model's 2 % bar, not held: the
// probes' kernel-weighted means of noisy particle pressures read it high at this size.
TEST(OpenBoundaries, WcsphCylinderInAChannelMeetsSchaeferTurek2D1) {
  Simulation<2> sim(load_case("cylinder_channel_wcsph_2d.yaml", {}));
  const Benchmark2D1 b = run_2d1(sim, 7.0, 6.0, "wcsph");
  testing::expect_figure({"2D-1 `wcsph` (0.005 m) C_D from the range's middle", "%", 2},
                         100 * (b.drag / kDragMiddle - 1), testing::Bound::within, 5);
  testing::report_limit({"2D-1 `wcsph` (0.005 m) pressure drop from the range's middle", "%", 2},
                        100 * (b.drop / kPressureDropMiddle - 1), testing::Bound::within, 2);
}

}  // namespace
}  // namespace sluice
