// Collisions between free bodies (VALIDATION.md C6, C7), no fluid.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "contact_support.hpp"

namespace sluice {
namespace {

// C7: squares 0.2 m (2D, x-z plane) of 1.5, 3.0 and 1.2 kg at +1, -0.5 and 0 m/s along x,
// E = 15 MPa, nu = 0.3, elastic. Rigid-body sequence: 1 and 2 collide, then 2 and 3.
TEST(ThreeBodyCollision2D, MomentumAndFinalVelocities) {
  const ContactMaterial material{15e6, 0.3, 1.0, 0.0};
  const double side = 0.2, dx = 0.01;
  MultibodySystem system(dx, Vec3::Zero());
  const double masses[3] = {1.5, 3.0, 1.2}, speeds[3] = {1.0, -0.5, 0.0}, x0[3] = {0.0, 0.3, 0.6};
  for (int b = 0; b < 3; ++b) {
    ContactBody body = testing::body_from_sample(
        sample_box_body(Vec3(side, side, side), dx, 0, 2),
        with_mass(box_mass_properties(Vec3(side, 1.0, side), 1.0), masses[b]), material,
        0.5 * side);
    body.state.position = Vec3(x0[b], 0, 0);
    body.state.velocity = Vec3(speeds[b], 0, 0);
    body.state.locked_translation = {false, true, false};
    body.state.locked_rotation = {true, false, true};
    system.add(body);
  }
  auto momentum = [&] {
    Vec3 p = Vec3::Zero();
    for (const auto& b : system.bodies()) p += b.state.mass * b.state.velocity;
    return p;
  };
  const double scale = 1.5 * 1.0 + 3.0 * 0.5;  // sum of |m v|
  double worst = 0;
  for (int step = 0; step < 1000; ++step) {
    system.advance(1e-3);
    worst = std::max(worst, momentum().norm() / scale);
  }
  // Elastic 1D collisions: (1, 2) -> (-1, 0.5); then (2, 3) -> (3 - 1.2) 0.5 / 4.2, 6 * 0.5 / 4.2.
  const double expected[3] = {-1.0, 1.8 * 0.5 / 4.2, 3.0 / 4.2};
  std::printf(
      "C7: momentum error %.2g (relative), final velocities %.4f %.4f %.4f (expected %.4f %.4f "
      "%.4f)\n",
      worst, system.bodies()[0].state.velocity[0], system.bodies()[1].state.velocity[0],
      system.bodies()[2].state.velocity[0], expected[0], expected[1], expected[2]);
  EXPECT_LT(worst, 1e-9);
  for (int b = 0; b < 3; ++b) {
    EXPECT_NEAR(system.bodies()[b].state.velocity[0], expected[b], 0.02) << "body " << b;
  }
}

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
  EXPECT_LT(worst, 0.01);
  EXPECT_GE(ratio, 3.0);
}

}  // namespace
}  // namespace sluice
