// Solid sub-cycling (VALIDATION.md C6), no fluid: against the same run at the solid step
// throughout, through the multibody system directly (C1, C3-C5 and C7 run from case files in
// test_contact_cases.cpp, C2 in test_bodies_in_water.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "contact_support.hpp"
#include "reported_figure.hpp"

namespace sluice {
namespace {

// C6: a bouncing ball with sub-cycling against the same run at the solid step throughout:
// the same trajectory within 1 %, at a third of the solid steps or fewer.
TEST(SubCycling, SameTrajectoryForFarFewerSolidSteps) {
  const ContactMaterial material{1e8, 0.3, 0.9, 0.3};
  const double dx = 0.01, radius = 0.1;
  auto make = [&] {
    MultibodySystem system(dx, Vec3(0, 0, -9.81));
    system.add(testing::floor_patch(0.2, dx, material));
    ContactBody ball = testing::sphere_body(radius, dx, material);
    ball.state.position = Vec3(0, 0, radius + 0.1);
    system.add(ball);
    return system;
  };
  MultibodySystem cycled = make();
  MultibodySystem reference = make();
  // The solid step the contact needs, taken everywhere by the reference run: what the
  // sub-cycled run uses at its first impact.
  MultibodySystem probe = make();
  int most = 1;
  for (int step = 0; step < 300; ++step) most = std::max(most, probe.advance(1e-3));
  const double solid_step = 1e-3 / most;
  double worst = 0;
  const double span = 0.1;  // the drop height above the floor, the trajectory's scale
  for (int step = 0; step < 1000; ++step) {
    cycled.advance(1e-3);
    const int inner = static_cast<int>(std::lround(1e-3 / solid_step));
    for (int k = 0; k < inner; ++k) reference.advance(1e-3 / inner);
    worst = std::max(worst, std::abs(cycled.bodies()[1].state.position[2] -
                                     reference.bodies()[1].state.position[2]) /
                                span);
  }
  const double ratio = double(reference.substeps_taken()) / cycled.substeps_taken();
  std::printf("C6: trajectory difference %.3g %% of the drop, %ld vs %ld solid steps (%.1fx)\n",
              100 * worst, cycled.substeps_taken(), reference.substeps_taken(), ratio);
  testing::expect_figure({"C6 trajectory difference", "% of the drop", 3}, 100 * worst,
                         testing::Bound::below, 1);
  testing::expect_figure({"C6 fewer solid steps", "times", 1}, ratio, testing::Bound::above, 3);
}

}  // namespace
}  // namespace sluice
