// The smooth start (core/smooth_ramp.hpp): nothing before it, full strength from its end, half
// way at its middle, a rate that is the share's derivative and an integral that is the share's.
#include <gtest/gtest.h>

#include "sluice/core/smooth_ramp.hpp"

namespace sluice {
namespace {

TEST(SmoothRamp, RisesFromNothingToFullStrengthWithItsRateAndIntegral) {
  const double ramp = 2;
  EXPECT_EQ(smooth_ramp(-1, ramp).share, 0.0);
  EXPECT_EQ(smooth_ramp(0, ramp).share, 0.0);
  EXPECT_NEAR(smooth_ramp(1, ramp).share, 0.5, 1e-15);
  EXPECT_EQ(smooth_ramp(2, ramp).share, 1.0);
  EXPECT_EQ(smooth_ramp(3, ramp).rate, 0.0);
  EXPECT_NEAR(smooth_ramp(3, ramp).integral, 2.0, 1e-15);  // a second behind: T / 2
  const double t = 0.7, h = 1e-6;
  EXPECT_NEAR(smooth_ramp(t, ramp).rate,
              (smooth_ramp(t + h, ramp).share - smooth_ramp(t - h, ramp).share) / (2 * h), 1e-8);
  EXPECT_NEAR(smooth_ramp(t, ramp).share,
              (smooth_ramp(t + h, ramp).integral - smooth_ramp(t - h, ramp).integral) / (2 * h),
              1e-8);
  // Without a ramp: full strength at once.
  EXPECT_EQ(smooth_ramp(0, 0).share, 1.0);
  EXPECT_EQ(smooth_ramp(0.5, 0).integral, 0.5);
}

}  // namespace
}  // namespace sluice
