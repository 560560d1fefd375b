// The Tait equation of state and its inverse.
#include "sluice/fluid/wcsph/tait.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace sluice {
namespace {

TEST(Tait, InverseReturnsTheDensity) {
  for (double gamma : {7.0, 1.0, 3.5}) {
    const TaitEquation eos(1000, 30, gamma);
    EXPECT_EQ(eos.pressure(1000), 0) << gamma;
    for (double rho : {980.0, 999.9, 1000.0, 1003.0, 1050.0}) {
      EXPECT_NEAR(eos.density(eos.pressure(rho)), rho, 1e-9 * rho) << gamma << " " << rho;
    }
  }
}

TEST(Tait, StiffnessAndSoundSpeed) {
  const TaitEquation eos(1000, 30, 7);
  EXPECT_DOUBLE_EQ(eos.stiffness, 30.0 * 30 * 1000 / 7);
  // dp/drho at rest is c0^2.
  const double h = 1e-4;
  EXPECT_NEAR((eos.pressure(1000 + h) - eos.pressure(1000 - h)) / (2 * h), 900, 1e-4);
  // Gamma 7 uses the product form; it agrees with the power.
  EXPECT_NEAR(eos.pressure(1010), eos.stiffness * (std::pow(1.01, 7) - 1), 1e-9);
}

TEST(Tait, TensionBeyondTheEquationIsClamped) {
  const TaitEquation eos(1000, 30, 7);
  const double clamped = 1000 * std::pow(1e-6, 1.0 / 7);  // 139 kg/m^3
  EXPECT_DOUBLE_EQ(eos.density(-2 * eos.stiffness), clamped);
  EXPECT_DOUBLE_EQ(eos.density(-eos.stiffness), clamped);
}

// negative_pressure: clamp gives no pressure below zero, and leaves the compressed side and the
// inverse as they were; keep (wcsph's default) gives the equation's tension.
TEST(Tait, NegativePressureClampedOrKept) {
  const TaitEquation kept(1000, 30, 7), clamped(1000, 30, 7, true);
  EXPECT_LT(kept.pressure(990), -800.0);
  EXPECT_EQ(clamped.pressure(990), 0.0);
  EXPECT_EQ(clamped.pressure(1000), 0.0);
  EXPECT_DOUBLE_EQ(clamped.pressure(1010), kept.pressure(1010));
  EXPECT_DOUBLE_EQ(clamped.density(-500), kept.density(-500));
}

// The density the model floors its particles at: the inverse's own bound, clamped or not.
TEST(Tait, LowestDensityIsTheInversesBound) {
  const TaitEquation kept(1000, 30, 7), clamped(1000, 30, 7, true);
  EXPECT_DOUBLE_EQ(kept.lowest_density, 1000 * std::pow(1e-6, 1.0 / 7));
  EXPECT_EQ(clamped.lowest_density, kept.lowest_density);
  EXPECT_EQ(kept.lowest_density, kept.density(-kept.stiffness));
}

}  // namespace
}  // namespace sluice
