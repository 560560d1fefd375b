// Linear wave theory and wavemaker theory (waves/): the dispersion relation, Biésel's transfer
// functions against their textbook forms and limits, a paddle signal's velocity as the rate of
// its displacement, and a JONSWAP sea's height, peak and seed.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <utility>

#include "sluice/waves/jonswap.hpp"
#include "sluice/waves/linear_waves.hpp"
#include "sluice/waves/paddle_signal.hpp"
#include "sluice/waves/paddle_transfer.hpp"
#include "sluice/waves/second_order_wavemaker.hpp"

namespace sluice::waves {
namespace {

constexpr double kG = 9.81;

TEST(LinearWaves, WavenumberSolvesTheDispersionRelationFromShallowToDeepWater) {
  for (double kh : {0.01, 0.1, 0.5, 1.0, 2.0, 5.0, 20.0}) {
    const double depth = 0.5, k = kh / depth;
    const double omega = std::sqrt(kG * k * std::tanh(kh));
    EXPECT_NEAR(wavenumber(omega, depth, kG), k, 1e-12 * k) << "kh " << kh;
    EXPECT_NEAR(angular_frequency(k, depth, kG), omega, 1e-12 * omega);
  }
  // Deep water: L = g T^2 / (2 pi), 1.5613 m for T = 1 s.
  EXPECT_NEAR(2 * std::numbers::pi / wavenumber(2 * std::numbers::pi, 100, kG), 1.5613, 1e-4);
}

TEST(LinearWaves, BreakingHeightIsMichesLimit) {
  // Deep water: H / L = 0.142; shallow: H / h = 0.142 * 2 pi = 0.89.
  const double k = 1;
  EXPECT_NEAR(breaking_height(k, 100) * k / (2 * std::numbers::pi), 0.142, 1e-12);
  EXPECT_NEAR(breaking_height(0.01, 1.0) / 1.0, 0.142 * 2 * std::numbers::pi, 2e-4);
}

TEST(PaddleTransfer, PistonAndBedHingedFlapMatchDeanAndDalrymple) {
  for (double kh : {0.1, 0.5, 1.0, 2.0, 4.0}) {
    const double h = 0.5, k = kh / h;
    const double piston = 2 * (std::cosh(2 * kh) - 1) / (std::sinh(2 * kh) + 2 * kh);
    const double flap = 4 * (std::sinh(kh) / kh) * (kh * std::sinh(kh) - std::cosh(kh) + 1) /
                        (std::sinh(2 * kh) + 2 * kh);
    EXPECT_NEAR(height_over_stroke(k, h, kPistonHinge), piston, 1e-12) << "kh " << kh;
    EXPECT_NEAR(height_over_stroke(k, h, h), flap, 1e-12) << "kh " << kh;
  }
  // Shallow water: H/S = kh (piston), kh / 2 (flap); deep water both 2.
  EXPECT_NEAR(height_over_stroke(0.002, 1, kPistonHinge), 0.002, 1e-8);
  EXPECT_NEAR(height_over_stroke(0.002, 1, 1), 0.001, 1e-8);
  EXPECT_NEAR(height_over_stroke(30, 1, kPistonHinge), 2, 1e-9);
  EXPECT_NEAR(height_over_stroke(30, 1, 1), 2 - 2.0 / 30, 1e-9);
}

// Biésel's integral by the midpoint rule, for a flap hinged d below the still water line.
double integrated_height_over_stroke(double k, double h, double d) {
  const int n = 200000;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double z = -h + (i + 0.5) * h / n;
    const double shape = z >= -d ? 1 + z / d : 0;
    sum += shape * k * std::cosh(k * (h + z)) * h / n;
  }
  return 4 * std::sinh(k * h) / (std::sinh(2 * k * h) + 2 * k * h) * sum;
}

TEST(PaddleTransfer, FlapsHingedAboveAndBelowTheBedMatchTheIntegral) {
  const double h = 0.5;
  for (double kh : {0.5, 1.0, 2.0}) {
    const double k = kh / h;
    for (double d : {0.3, 0.5, 0.8}) {
      EXPECT_NEAR(height_over_stroke(k, h, d), integrated_height_over_stroke(k, h, d), 1e-8)
          << "kh " << kh << ", hinge " << d << " m down";
    }
  }
}

TEST(PaddleTransfer, MadsensSecondHarmonicCancelsALongWavesBoundHarmonic) {
  // In shallow water the correction adds to the stroke (3 cosh kh / sinh^3 kh outweighs 2/(H/S)),
  // and in deep water it is -H^2 / (32 h) (2 / (H/S) = 1, the first term vanishing).
  EXPECT_GT(madsen_second_harmonic(0.05, 0.4 / 0.5, 0.5), 0);
  EXPECT_NEAR(madsen_second_harmonic(0.05, 40, 0.5), -0.05 * 0.05 / (32 * 0.5), 1e-12);
}

// Schäffer's (1996) superharmonic F for a flap hinged at the bed of water 0.5 m deep, against an
// independent numpy implementation of the same sums (docs/notes/flap_second_order.md, section
// 3.1: extrapolated from 400 and 800 evanescent modes), whose own derivation from the boundary
// value problem agreed with the closed form to 1e-13. The sums converge as 1 / modes: the
// default (400 and 800, extrapolated) reproduces the table's digits.
TEST(SecondOrderWavemaker, FlapMatchesTheReferenceSums) {
  const double h = 0.5;
  const struct {
    double kh;
    std::complex<double> f;
  } table[] = {
      {0.5, {5.086352, -0.524993}}, {1.0, {-1.462085, -0.691992}}, {2.0, {-0.673006, -0.031254}}};
  for (const auto& row : table) {
    const double omega = angular_frequency(row.kh / h, h, kG);
    const std::complex<double> f = schaffer_second_order(omega, h, h, kG);
    EXPECT_NEAR(f.real(), row.f.real(), 2e-6 * std::abs(row.f)) << "kh " << row.kh;
    EXPECT_NEAR(f.imag(), row.f.imag(), 2e-6 * std::abs(row.f)) << "kh " << row.kh;
  }
  // Hinged 0.2 m above the bed (the part below it still) and 0.3 m below it, at kh = 1 (the
  // notes' section 3.4).
  const double omega = angular_frequency(1 / h, h, kG);
  for (const auto& [hinge, expected] :
       {std::pair{0.3, std::complex<double>{-6.247943, -3.502204}},
        std::pair{0.8, std::complex<double>{-0.125155, -0.118720}}}) {
    const std::complex<double> f = schaffer_second_order(omega, h, hinge, kG);
    // 2e-6 of it, and the table's sixth decimal.
    EXPECT_NEAR(std::abs(f - expected), 0, 2e-6 * std::abs(expected) + 1e-6) << "hinge " << hinge;
  }
}

// A piston in shallow water: Schäffer's theory tends to Madsen's (1971) long-wave formula, a
// depth-integrated flux balance that leaves out the evanescent modes (0.006 % apart at
// kh = 0.1); beyond kh of about 0.3 they part (section 2.2 of the notes).
TEST(SecondOrderWavemaker, PistonTendsToMadsenInShallowWater) {
  const double h = 0.5, kh = 0.1, k = kh / h, a = 0.001;
  const std::complex<double> f =
      schaffer_second_order(angular_frequency(k, h, kG), h, kPistonHinge, kG);
  const double madsen = madsen_second_harmonic(2 * a, k, h);
  EXPECT_NEAR(a * a * std::abs(f) / madsen - 1, 0, 2e-4);
  EXPECT_NEAR(std::arg(f), 0, 1e-3);  // in phase with sin 2 omega t, as Madsen's
  // At kh = 1 Madsen's is 0.28 of Schäffer's (the notes' table 3.2: 2.01e-4 against 7.21e-4 m).
  const std::complex<double> deeper =
      schaffer_second_order(angular_frequency(1 / h, h, kG), h, kPistonHinge, kG);
  EXPECT_GT(a * a * std::abs(deeper) / madsen_second_harmonic(2 * a, 1 / h, h), 3);
}

// A flap's second-order signal carries Schäffer's harmonic, at twice the frequency and shifted
// by arg F.
TEST(PaddleSignal, FlapsSecondOrderIsSchaeffersHarmonic) {
  const double h = 0.5, omega = angular_frequency(2.0, h, kG), a = 0.03;  // kh = 1
  const PaddleSignal s = paddle_signal({{a, omega, 0.4}}, h, h, kG, true, 0);
  ASSERT_EQ(s.parts.size(), 2u);
  const std::complex<double> f = schaffer_second_order(omega, h, h, kG);
  EXPECT_NEAR(s.parts[1].amplitude, a * a * std::abs(f), 1e-15);
  EXPECT_EQ(s.parts[1].omega, 2 * omega);
  EXPECT_NEAR(s.parts[1].phase, 0.8 + std::arg(f), 1e-15);
}

TEST(PaddleSignal, VelocityIsTheRateOfTheDisplacementThroughTheRamp) {
  const std::vector<WaveComponent> sea{{0.03, 4.0, 0.3}, {0.01, 7.0, 2.0}};
  for (bool second_order : {false, true}) {
    const PaddleSignal s = paddle_signal(sea, 0.5, kPistonHinge, kG, second_order, 2.0);
    EXPECT_EQ(s.parts.size(), second_order ? 4u : 2u);
    EXPECT_EQ(s.displacement(0), 0);
    EXPECT_EQ(s.velocity(0), 0);
    for (double t : {0.3, 1.0, 1.99, 2.5, 7.0}) {
      const double e = 1e-6;
      const double rate = (s.displacement(t + e) - s.displacement(t - e)) / (2 * e);
      EXPECT_NEAR(s.velocity(t), rate, 1e-7) << "t " << t;
    }
  }
}

TEST(PaddleSignal, StrokeIsTheHeightOverTheTransferFunction) {
  const double h = 0.5, k = 1 / h, omega = angular_frequency(k, h, kG), a = 0.02;
  const PaddleSignal s = paddle_signal({{a, omega, 0}}, h, h, kG, false, 0);
  ASSERT_EQ(s.parts.size(), 1u);
  EXPECT_NEAR(2 * s.parts[0].amplitude, 2 * a / height_over_stroke(k, h, h), 1e-15);
  // The paddle moves forward fastest at t = 0, under the crest.
  EXPECT_NEAR(s.velocity(0), s.parts[0].amplitude * omega, 1e-15);
}

// What active absorption relies on: a first-order paddle's velocity is omega / (H/S) times the
// elevation it makes, in phase (a crest as it moves forward fastest).
TEST(PaddleSignal, VelocityIsTheGainTimesTheFirstOrderElevation) {
  const double h = 0.5, a = 0.02, phase = 0.4;
  for (double hinge : {kPistonHinge, h, 0.7 * h}) {
    for (double kh : {0.5, 1.0, 2.0}) {
      const double k = kh / h, omega = angular_frequency(k, h, kG);
      const PaddleSignal one = paddle_signal({{a, omega, phase}}, h, hinge, kG, false, 0);
      const double gain = omega / height_over_stroke(k, h, hinge);
      // One train: its surface carries the bound harmonic too, which the paddle does not make.
      const double bound = stokes_second_harmonic(a, k, h);
      for (double t : {0.0, 0.7, 3.1}) {
        EXPECT_NEAR(one.velocity(t),
                    gain * (one.elevation(t) - bound * std::cos(2 * (omega * t + phase))), 1e-14)
            << "kh " << kh << " t " << t;
      }
      // A sea of two: their first-order sum, no bound harmonics.
      const PaddleSignal two =
          paddle_signal({{a, omega, phase}, {a, omega, phase + 1}}, h, hinge, kG, false, 0);
      EXPECT_NEAR(two.velocity(1.3), gain * two.elevation(1.3), 1e-14);
    }
  }
  // Ramped as the displacement is: nothing at the start.
  EXPECT_EQ(paddle_signal({{a, 2.0, phase}}, h, kPistonHinge, kG, true, 2.0).elevation(0), 0);
}

TEST(LinearWaves, StokesSecondHarmonicMeetsItsDeepAndShallowLimits) {
  // Deep water: k a^2 / 2; shallow: 3 a^2 / (4 k^2 h^3).
  const double a = 0.05, k = 3.0;
  EXPECT_NEAR(stokes_second_harmonic(a, k, 20.0), 0.5 * k * a * a, 1e-12);
  const double h = 0.001 / k;
  EXPECT_NEAR(stokes_second_harmonic(a, k, h) / (3 * a * a / (4 * k * k * h * h * h)), 1.0, 1e-5);
}

TEST(Jonswap, ComponentsHoldTheSignificantHeightPeakAndSeed) {
  JonswapSea sea;
  sea.significant_height = 0.1;
  sea.peak_period = 1.5;
  sea.min_frequency = 0.3;
  sea.max_frequency = 2.0;
  sea.components = 300;
  const auto waves = jonswap_components(sea);
  ASSERT_EQ(waves.size(), 300u);
  double m0 = 0, largest = 0, at_largest = 0;
  for (const auto& w : waves) {
    m0 += w.amplitude * w.amplitude / 2;
    EXPECT_GE(w.phase, 0);
    EXPECT_LT(w.phase, 2 * std::numbers::pi);
    if (w.amplitude > largest) {
      largest = w.amplitude;
      at_largest = w.omega / (2 * std::numbers::pi);
    }
  }
  EXPECT_NEAR(4 * std::sqrt(m0), 0.1, 1e-12);
  EXPECT_NEAR(at_largest, 1 / 1.5, (sea.max_frequency - sea.min_frequency) / 300);
  // The shape peaks at f_p; the peak enhancement multiplies it there by gamma.
  const double fp = 1 / 1.5;
  EXPECT_NEAR(jonswap_shape(fp, fp, 3.3) / jonswap_shape(fp, fp, 1.0), 3.3, 1e-12);
  EXPECT_GT(jonswap_shape(fp, fp, 3.3), jonswap_shape(1.02 * fp, fp, 3.3));
  EXPECT_GT(jonswap_shape(fp, fp, 3.3), jonswap_shape(0.98 * fp, fp, 3.3));
  // The same seed draws the same sea; another seed another.
  EXPECT_EQ(jonswap_components(sea)[17].phase, waves[17].phase);
  sea.seed = 2;
  EXPECT_NE(jonswap_components(sea)[17].phase, waves[17].phase);
}

}  // namespace
}  // namespace sluice::waves
