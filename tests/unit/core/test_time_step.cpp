// The steps towards an output's time (core/time_step.hpp): equal, none above the stable step,
// landing exactly on the time, and no extra step for a remainder that is only rounding.
#include <gtest/gtest.h>

#include <vector>

#include "sluice/core/time_step.hpp"

namespace sluice {
namespace {

// The steps from 0 to `until` with `stable` the model's step throughout.
std::vector<double> steps_to(double until, double stable) {
  std::vector<double> taken;
  double t = 0;
  while (t < until && taken.size() < 1000) {
    const double dt = step_towards(until - t, stable);
    taken.push_back(dt);
    t += dt;
  }
  return taken;
}

TEST(StepTowards, EqualStepsNoneAboveTheStableOneLandOnTheTime) {
  // F3 at 0.015 m: a 0.62 ms stable step to each 1 ms probe. Taking 0.62 then 0.38 ms made
  // the MPS pressure alternate; two steps of 0.5 ms do not.
  const std::vector<double> probe = steps_to(1e-3, 0.62e-3);
  ASSERT_EQ(probe.size(), 2u);
  EXPECT_NEAR(probe[0], 0.5e-3, 1e-15);
  EXPECT_NEAR(probe[1], 0.5e-3, 1e-15);
  // Ten milliseconds in steps of at most 0.62: seventeen of 10 / 17 ms.
  const std::vector<double> frame = steps_to(1e-2, 0.62e-3);
  ASSERT_EQ(frame.size(), 17u);
  double sum = 0;
  for (const double dt : frame) {
    EXPECT_LE(dt, 0.62e-3);
    EXPECT_NEAR(dt, 1e-2 / 17, 1e-15);
    sum += dt;
  }
  EXPECT_NEAR(sum, 1e-2, 1e-15);
}

TEST(StepTowards, AWholeNumberOfStepsUpToRoundingTakesNoExtraStep) {
  EXPECT_EQ(step_towards(1e-3, 1e-3), 1e-3);
  EXPECT_EQ(step_towards(1e-3 * (1 + 1e-12), 1e-3), 1e-3 * (1 + 1e-12));  // stretched, not split
  EXPECT_EQ(steps_to(3e-3 * (1 + 1e-12), 1e-3).size(), 3u);
  // Nearer than the stable step: one step, the whole of it.
  EXPECT_EQ(step_towards(0.3e-3, 1e-3), 0.3e-3);
}

}  // namespace
}  // namespace sluice
