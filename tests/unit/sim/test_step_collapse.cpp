// The time-step collapse rule: a step below kCollapseFraction of the first, or one that would
// need more than kMostSteps to the end, is named with what limits it; others pass.
#include <gtest/gtest.h>

#include <limits>

#include "sluice/sim/step_collapse.hpp"

namespace sluice {
namespace {

TEST(StepCollapse, AStepThatShrinksTenfoldIsFine) {
  const TimeStep first{1e-4, "the speed of sound and the flow speed"};
  EXPECT_FALSE(
      collapsed_step(TimeStep{1e-5, "the largest acceleration"}, first, 0.5, 1.0, "wcsph"));
}

TEST(StepCollapse, BelowTheFractionOfTheFirstStepIsNamed) {
  const TimeStep first{1e-4, "the speed of sound and the flow speed"};
  const TimeStep step{0.5 * kCollapseFraction * 1e-4, "the largest acceleration"};
  const auto why = collapsed_step(step, first, 0.5, 0.5 + 1e-3, "wcsph");
  ASSERT_TRUE(why);
  EXPECT_EQ(*why,
            "the time step collapsed to 5e-09 s, limited by the largest acceleration in the wcsph "
            "model: below 1e-04 of the first step (0.0001 s)");
}

TEST(StepCollapse, MoreThanTheMostStepsToTheEndIsNamed) {
  const TimeStep first{1e-10, "the viscosity"};
  const auto why = collapsed_step(first, first, 0, 1.0, "mps");
  ASSERT_TRUE(why);
  EXPECT_EQ(
      *why,
      "the time step collapsed to 1e-10 s, limited by the viscosity in the mps model: the 1 s "
      "left would take 1e+10 steps, more than 1e+09");
  EXPECT_FALSE(collapsed_step(first, first, 1.0 - 1e-3, 1.0, "mps"));  // 1e7 steps left
}

TEST(StepCollapse, ANanOrZeroStepCollapses) {
  const TimeStep first{1e-4, "the viscosity"};
  EXPECT_TRUE(collapsed_step(TimeStep{0.0, "the viscosity"}, first, 0, 1.0, "mac"));
  const TimeStep nan{std::numeric_limits<double>::quiet_NaN(), "the flow speed and gravity"};
  EXPECT_TRUE(collapsed_step(nan, first, 0, 1.0, "mac"));
}

TEST(StepCollapse, TighteningKeepsTheSmallestAndItsName) {
  TimeStep step;
  step.tighten(1e-3, "a");
  step.tighten(1e-2, "b");
  step.tighten(1e-4, "c");
  EXPECT_EQ(step.dt, 1e-4);
  EXPECT_STREQ(step.limit, "c");
}

}  // namespace
}  // namespace sluice
