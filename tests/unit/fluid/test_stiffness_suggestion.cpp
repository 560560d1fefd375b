// The penalty barrier of a layer of solid particles, worked by hand
// (fluid/penalty_sph/stiffness_suggestion.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "sluice/fluid/penalty_sph/stiffness_suggestion.hpp"

namespace sluice {
namespace {

TEST(StiffnessSuggestion, BarrierAtThePoreCentreByHand) {
  // Seed 002's model 2: L_b = 0.002 m, l0 = 0.00328 m, reach 0.00264 m. At the pore centre
  // the four nearest solids are L_b / sqrt(2) away and the next ones beyond the reach:
  // 4 (0.00264 - 0.0014142)^2 / 2.
  const Real reach = (0.002 + 0.00328) / 2;
  const Real by_hand = 2 * std::pow(reach - 0.002 / std::sqrt(2.0), 2);
  EXPECT_NEAR(penalty_barrier<3>(0.002, reach), by_hand, 1e-6 * by_hand);
  // In 2D, a row: the gap's centre is L_b / 2 from two solids.
  EXPECT_NEAR(penalty_barrier<2>(0.002, reach), std::pow(reach - 0.001, 2), 1e-12);
}

TEST(StiffnessSuggestion, OpenPoresHoldNothingBack) {
  // Seed 002's model 3: L_b = 0.01 m, l0 = 0.00204 m: the pore centre is 7.1 mm from the
  // grains, beyond the reach of 6.0 mm.
  const Real barrier = penalty_barrier<3>(0.01, (0.01 + 0.00204) / 2);
  EXPECT_EQ(barrier, 0);
  EXPECT_TRUE(std::isinf(suggested_penalty_stiffness(barrier, 8.5e-6, 2.43)));
}

TEST(StiffnessSuggestion, KineticEnergyOverTheBarrier) {
  // 1/2 m v^2 / barrier: 1 g at 2 m/s over 1e-5 m^2 needs 200 N/m.
  EXPECT_NEAR(suggested_penalty_stiffness(1e-5, 1e-3, 2.0), 200.0, 1e-9);
}

}  // namespace
}  // namespace sluice
