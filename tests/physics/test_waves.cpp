// Waves against linear wavemaker theory: cases/wave_flume_2d.yaml, a piston making regular
// waves of steepness 0.02 at kh = 1 in water 0.5 m deep (Biésel's stroke with Madsen's second
// order), absorbed by a damping zone at the far end. The gauges two wavelengths from the paddle
// and a quarter wavelength beyond give the incident wave's height and the reflection
// coefficient (Goda & Suzuki 1976). validation/wave_flume.py runs the other depths, the flap and
// an irregular sea (docs/validation.md, F8).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "physics_support.hpp"
#include "reported_figure.hpp"
#include "sluice/waves/linear_waves.hpp"
#include "sluice/waves/wave_analysis.hpp"

namespace sluice {
namespace {

using testing::load_case;
using testing::run_until;

// mac at 0.02 m cells (3 across the wave's height, 157 along its length) to 20 s; the last six
// periods, after the waves have gone to the damping zone and what it returns has come back:
// the incident height within 5 % of the target (measured 0.9 % below it) and the reflection
// coefficient below 10 % (measured 0.6 %; 140 s on one thread).
TEST(Waves, PistonMakesBieselsHeightAndTheDampingZoneAbsorbsIt) {
  Simulation<2> sim(load_case("wave_flume_2d.yaml"));
  const double depth = 0.5, height = 0.0628, period = 1.6254, end = 20.0;
  const double omega = 2 * std::numbers::pi / period;
  const double k = waves::wavenumber(omega, depth, 9.81);
  const double x1 = 6.483, x2 = 7.268;  // 2 L from the paddle's face at 0.2 m, and L/4 beyond
  const FluidObservation& fluid = sim.fluid().observation();
  std::vector<double> t, e1, e2;
  run_until(sim, end, [&](const StepClock& c) {
    if (c.time < end - 6 * period) return;
    t.push_back(c.time);
    e1.push_back(fluid.water_height_at(Vec3(x1, 0, 0)) - depth);
    e2.push_back(fluid.water_height_at(Vec3(x2, 0, 0)) - depth);
  });
  const waves::IncidentAndReflected r = waves::incident_and_reflected(
      waves::harmonic(t, e1, omega), x1, waves::harmonic(t, e2, omega), x2, k);
  std::printf("kh = 1 piston (mac, 0.02 m): incident H %.5f m (target %.4f), reflection %.4f\n",
              2 * r.incident, height, r.coefficient());
  testing::expect_figure({"F8 kh = 1 piston (`mac`, 0.02 m) incident height from Biésel's", "%", 2},
                         100 * (2 * r.incident / height - 1), testing::Bound::within, 5);
  testing::expect_figure({"F8 kh = 1 piston (`mac`, 0.02 m) reflection coefficient", "%", 2},
                         100 * r.coefficient(), testing::Bound::below, 10);
}

}  // namespace
}  // namespace sluice
