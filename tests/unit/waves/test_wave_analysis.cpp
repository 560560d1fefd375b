// Wave gauge analysis (waves/wave_analysis.hpp) on records made of known waves: a harmonic, the
// incident and reflected amplitudes two gauges see, a sea's H_m0 and peak period.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sluice/waves/wave_analysis.hpp"

namespace sluice::waves {
namespace {

TEST(WaveAnalysis, HarmonicRecoversAmplitudeAndPhaseBesideOtherParts) {
  const double omega = 3.0;
  std::vector<double> t, v;
  for (int i = 0; i < 4000; ++i) {
    t.push_back(i * 0.005);
    v.push_back(0.02 * std::cos(omega * t.back() - 0.7) + 0.004 * std::cos(2 * omega * t.back()) +
                0.01);
  }
  // 20 s hold 9.55 periods: the other parts leak a little into the fit.
  const std::complex<double> z = harmonic(t, v, omega);
  EXPECT_NEAR(std::abs(z), 0.02, 2e-4);
  EXPECT_NEAR(std::arg(z), 0.7, 1e-2);
}

TEST(WaveAnalysis, GodaSuzukiSeparatesIncidentAndReflectedWaves) {
  const double k = 2.0, omega = 4.4, incident = 0.03, reflected = 0.006;
  const double x1 = 3.0, x2 = 3.4;  // k dx = 0.8, away from multiples of pi
  std::vector<double> t, e1, e2;
  for (int i = 0; i < 2000; ++i) {
    t.push_back(i * 0.01);
    auto elevation = [&](double x) {
      return incident * std::cos(k * x - omega * t.back() + 0.2) +
             reflected * std::cos(k * x + omega * t.back() + 1.1);
    };
    e1.push_back(elevation(x1));
    e2.push_back(elevation(x2));
  }
  const IncidentAndReflected r =
      incident_and_reflected(harmonic(t, e1, omega), x1, harmonic(t, e2, omega), x2, k);
  EXPECT_NEAR(r.incident, incident, 2e-4);
  EXPECT_NEAR(r.reflected, reflected, 2e-4);
  EXPECT_NEAR(r.coefficient(), 0.2, 1e-2);
}

TEST(WaveAnalysis, SignificantHeightAndPeakPeriodOfKnownRecords) {
  std::vector<double> v;
  const double dt = 0.02;
  for (int i = 0; i < 10000; ++i) {  // 200 s: 0.01 m at 1.25 s, 0.004 m at 0.8 s
    const double t = i * dt;
    v.push_back(0.01 * std::sin(2 * std::numbers::pi * t / 1.25) +
                0.004 * std::sin(2 * std::numbers::pi * t / 0.8 + 1.0) + 0.3);
  }
  // m0 = (0.01^2 + 0.004^2) / 2.
  EXPECT_NEAR(significant_height(v), 4 * std::sqrt((1e-4 + 1.6e-5) / 2), 1e-6);
  EXPECT_NEAR(peak_period(v, dt, 1, 3.0), 1.25, 1e-9);
  EXPECT_NEAR(peak_period(v, dt, 3, 3.0), 1.25, 1e-9);
}

}  // namespace
}  // namespace sluice::waves
