// Rigid bodies in contact through surface particles (VALIDATION.md C1, C3, C4), no fluid.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "contact_support.hpp"

namespace sluice {
namespace {

constexpr double kSpacing = 0.01;

ContactBody cube(double side, const ContactMaterial& m) {
  // Hertz radius of a cube: the radius of the sphere of the same volume.
  return testing::body_from_sample(sample_box_body(Vec3::Constant(side), kSpacing, 0, 3),
                                   box_mass_properties(Vec3::Constant(side), 1000.0), m,
                                   std::cbrt(3 / (4 * std::numbers::pi)) * side);
}

ContactBody sphere(double radius, const ContactMaterial& m) {
  return testing::sphere_body(radius, kSpacing, m);
}

ContactBody floor_body(double half_width, const ContactMaterial& m) {
  return testing::floor_patch(half_width, kSpacing, m);
}

// Drops a body so that it hits the floor at speed v0; returns rebound / impact normal speed,
// both taken at the instants the contact starts and ends.
double bounce_ratio(ContactBody body, double bottom_offset, const ContactMaterial& m, double v0) {
  const Vec3 g(0, 0, -9.81);
  MultibodySystem system(kSpacing, g);
  const double height = v0 * v0 / (2 * 9.81);
  body.state.position = Vec3(0, 0, bottom_offset + height);
  system.add(floor_body(0.3, m));
  const std::size_t id = system.add(body);
  double impact = 0, rebound = 0;
  bool touched = false;
  for (int step = 0; step < 20000; ++step) {
    const double before = system.bodies()[id].state.velocity[2];
    system.advance(1e-4);
    const bool touching = system.contact_force()[id].norm() > 0;
    if (touching && !touched) impact = -before;
    if (touched && !touching) {
      rebound = system.bodies()[id].state.velocity[2];
      break;
    }
    touched = touched || touching;
  }
  return rebound / impact;
}

class DropAndBounce : public ::testing::TestWithParam<double> {};

TEST_P(DropAndBounce, ReboundRatioIsRestitution) {
  const double e = GetParam();
  const ContactMaterial material{1e11, 0.3, e, 0.3};
  const double sphere_ratio = bounce_ratio(sphere(0.1, material), 0.1, material, 3.0);
  const double cube_ratio = bounce_ratio(cube(0.1, material), 0.05, material, 3.0);
  std::printf("C1: e = %.2f: sphere %.4f, cube %.4f\n", e, sphere_ratio, cube_ratio);
  EXPECT_NEAR(sphere_ratio, e, 0.03 * e);
  EXPECT_NEAR(cube_ratio, e, 0.03 * e);
}

INSTANTIATE_TEST_SUITE_P(C1, DropAndBounce, ::testing::Values(0.2, 0.5, 0.9));

// C4: a cube resting on its face stays put: drift below 1 mm, rotation below 0.1 degree.
TEST(RestingCube, StaysPutForFiveSeconds) {
  const ContactMaterial material{1e8, 0.3, 0.5, 0.5};
  MultibodySystem system(kSpacing, Vec3(0, 0, -9.81));
  system.add(floor_body(0.2, material));
  ContactBody box = cube(0.1, material);
  box.state.position = Vec3(0.003, -0.002, 0.05);  // off the floor lattice, just touching
  const std::size_t id = system.add(box);
  const Vec3 start = box.state.position;
  long substeps = 0;
  for (int step = 0; step < 5000; ++step) substeps += system.advance(1e-3);
  const auto& s = system.bodies()[id].state;
  const double angle = 2 * std::atan2(s.orientation.vec().norm(), std::abs(s.orientation.w()));
  std::printf(
      "C4: drift %.3g mm horizontal, settled %.3g mm, rotation %.3g deg, %.1f sub-steps per step\n",
      1e3 * (s.position - start).head<2>().norm(), 1e3 * (start[2] - s.position[2]),
      angle * 180 / std::numbers::pi, substeps / 5000.0);
  EXPECT_LT((s.position - start).head<2>().norm(), 1e-3);
  EXPECT_LT(std::abs(s.position[2] - start[2]), 1e-3);
  EXPECT_LT(angle * 180 / std::numbers::pi, 0.1);
}

// C3 with the incline made by tilting gravity: a block on a plane inclined by theta.
double slide_distance(double theta, double mu, double time) {
  const ContactMaterial material{1e8, 0.3, 0.5, mu};
  const Vec3 g = 9.81 * Vec3(std::sin(theta), 0, -std::cos(theta));
  MultibodySystem system(kSpacing, g);
  system.add(floor_body(0.6, material));
  ContactBody box = cube(0.1, material);
  box.state.position = Vec3(-0.4, 0, 0.05 - 1e-5);
  const std::size_t id = system.add(box);
  // Let the contact settle without the tangential pull, then release.
  for (int step = 0; step < static_cast<int>(time / 1e-3); ++step) system.advance(1e-3);
  return system.bodies()[id].state.position[0] + 0.4;
}

TEST(Incline, SlidesWithTheCoulombAcceleration) {
  const double theta = 30 * std::numbers::pi / 180, mu = 0.3, t = 0.5;
  const double expected = 0.5 * 9.81 * (std::sin(theta) - mu * std::cos(theta)) * t * t;
  const double travelled = slide_distance(theta, mu, t);
  std::printf("C3: slid %.5f m, analytic %.5f m\n", travelled, expected);
  EXPECT_NEAR(travelled, expected, 0.02 * expected);
}

TEST(Incline, StaysWhenFrictionHolds) {
  const double theta = 20 * std::numbers::pi / 180, mu = 0.5;  // tan 20 = 0.36 < 0.5
  const double creep = slide_distance(theta, mu, 2.0);
  std::printf("C3: creep %.3g mm in 2 s\n", 1e3 * creep);
  EXPECT_LT(std::abs(creep), 1e-3);
}

}  // namespace
}  // namespace sluice
