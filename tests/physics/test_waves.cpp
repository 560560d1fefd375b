// Waves against linear wavemaker theory: cases/wave_flume_2d.yaml, a piston making regular
// waves of steepness 0.02 at kh = 1 in water 0.5 m deep (Biésel's stroke with Madsen's second
// order), absorbed by a damping zone at the far end. The gauges two wavelengths from the paddle
// and a quarter wavelength beyond give the incident wave's height and the reflection
// coefficient (Goda & Suzuki 1976). validation/wave_flume.py runs the other depths, the flap and
// an irregular sea (docs/validation.md, F8). And a box floating in those waves, held to heave,
// against linear theory for a box long compared with its draft (cases/floating_box_waves_2d.yaml,
// F11).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "physics_support.hpp"
#include "reported_figure.hpp"
#include "sluice/waves/floating_response.hpp"
#include "sluice/waves/linear_waves.hpp"
#include "sluice/waves/wave_analysis.hpp"

namespace sluice {
namespace {

using testing::load_case;

constexpr double kDepth = 0.5;  // every flume's

// A regular wave of `period` on water kDepth deep, read at gauges x1 < x2 over the last
// `periods` periods before `end`: runs `sim` there, and returns the incident and reflected
// waves at the wave's frequency (Goda & Suzuki), calling also(clock) at each step read.
struct Gauges {
  double period, x1, x2;
  double omega() const { return 2 * std::numbers::pi / period; }
  double k() const { return waves::wavenumber(omega(), kDepth, 9.81); }

  template <class Also>
  waves::IncidentAndReflected read(Simulation<2>& sim, double end, double periods,
                                   Also&& also) const {
    const FluidObservation& fluid = sim.fluid().observation();
    std::vector<double> t, e1, e2;
    testing::run_until(sim, end, [&](const StepClock& c) {
      if (c.time < end - periods * period) return;
      t.push_back(c.time);
      e1.push_back(fluid.water_height_at(Vec3(x1, 0, 0)) - kDepth);
      e2.push_back(fluid.water_height_at(Vec3(x2, 0, 0)) - kDepth);
      also(c);
    });
    return waves::incident_and_reflected(waves::harmonic(t, e1, omega()), x1,
                                         waves::harmonic(t, e2, omega()), x2, k());
  }
  waves::IncidentAndReflected read(Simulation<2>& sim, double end, double periods) const {
    return read(sim, end, periods, [](const StepClock&) {});
  }
};

// mac at 0.02 m cells (3 across the wave's height, 157 along its length) to 20 s; the last six
// periods, after the waves have gone to the damping zone and what it returns has come back:
// the incident height within 5 % of the target (measured 0.9 % below it) and the reflection
// coefficient below 10 % (measured 0.7 %; 140 s on one thread).
TEST(Waves, PistonMakesBieselsHeightAndTheDampingZoneAbsorbsIt) {
  Simulation<2> sim(load_case("wave_flume_2d.yaml"));
  const double height = 0.0628;
  // 2 L from the paddle's face at 0.2 m, and L/4 beyond
  const waves::IncidentAndReflected r = Gauges{1.6254, 6.483, 7.268}.read(sim, 20.0, 6);
  std::printf("kh = 1 piston (mac, 0.02 m): incident H %.5f m (target %.4f), reflection %.4f\n",
              2 * r.incident, height, r.coefficient());
  testing::expect_figure({"F8 kh = 1 piston (`mac`, 0.02 m) incident height from Biésel's", "%", 2},
                         100 * (2 * r.incident / height - 1), testing::Bound::within, 5);
  testing::expect_figure({"F8 kh = 1 piston (`mac`, 0.02 m) reflection coefficient", "%", 2},
                         100 * r.coefficient(), testing::Bound::below, 10);
}

// The piston of F8 with active absorption before a wall two wavelengths away that sends every
// wave back (cases/paddle_absorption_2d.yaml), mac at 0.02 m to 22 s; the five periods after
// the first waves back have passed the gauges again: the wave leaving the paddle within 5 % of
// Biésel's height (measured -0.9 %) while the wall returns it whole (reflection coefficient
// 1.01, bar above 0.9: the check is not of a wave that never came back; 110 s on one thread).
// Without absorption the paddle sends the returning waves out again: +103 % over 14-22 s
// (docs/validation.md, F8).
TEST(Waves, ActiveAbsorptionTakesInWhatAClosedEndSendsBack) {
  Simulation<2> sim(load_case("paddle_absorption_2d.yaml"));
  const double height = 0.0628;
  // L from the paddle's face at 0.2 m, and L/4 beyond
  const waves::IncidentAndReflected r = Gauges{1.6254, 3.342, 4.127}.read(sim, 22.0, 5);
  std::printf(
      "absorbing piston before a wall (mac, 0.02 m): incident H %.5f m (target %.4f), "
      "reflection %.4f\n",
      2 * r.incident, height, r.coefficient());
  testing::expect_figure(
      {"F8 absorbing piston before a wall (`mac`, 0.02 m) incident height from Biésel's", "%", 2},
      100 * (2 * r.incident / height - 1), testing::Bound::within, 5);
  testing::expect_figure(
      {"F8 absorbing piston before a wall (`mac`, 0.02 m) the wall's reflection", "", 3},
      r.coefficient(), testing::Bound::above, 0.9);
}

// mac at 0.04 m cells (2 across the wave's height, 2.5 down the box's draft) to 18 s; the last
// five periods: the box's heave at the wave's frequency over the incident amplitude (Goda &
// Suzuki from the two gauges ahead of it) within 10 % of the Froude–Krylov prediction, 0.978
// (measured +1.5 % from every step; the script's rows every 0.02 s give +0.1 %; 50 s on one
// thread). A flat plate's added mass, rho pi B^2 / 8, would raise the prediction by 3 %: the bar
// holds either way.
TEST(Waves, FloatingBoxHeavesAsLinearTheoryPredicts) {
  Simulation<2> sim(load_case("floating_box_waves_2d.yaml", {"spacing=0.04"}));
  const double beam = 0.6, draft = 0.1;
  const std::size_t box = 1;
  // L / 2 from the paddle's face at 0.2 m, and L/4 beyond
  const Gauges gauges{2.055237, 2.294, 3.341};
  std::vector<double> t, heave;
  const waves::IncidentAndReflected r = gauges.read(sim, 18.0, 5, [&](const StepClock& c) {
    t.push_back(c.time);
    heave.push_back(sim.bodies().state(box).position[2]);
  });
  const double response = std::abs(waves::harmonic(t, heave, gauges.omega())) / r.incident;
  const double predicted =
      waves::box_heave_response(gauges.k(), gauges.omega(), kDepth, 9.81, beam, draft);
  std::printf(
      "floating box (mac, 0.04 m): incident a %.5f m, heave over it %.4f (predicted %.4f)\n",
      r.incident, response, predicted);
  testing::expect_figure(
      {"F11 floating box (`mac`, 0.04 m) heave response against linear theory", "%", 2},
      100 * (response / predicted - 1), testing::Bound::within, 10);
}

}  // namespace
}  // namespace sluice
