// The case's bodies as built for a run: exact mass properties, the particles the fluid sees
// half a spacing under the surface, the inside test that keeps fluid out of bodies, and the
// tank's sides as contact bodies.
#include <gtest/gtest.h>

#include "sluice/io/case_config.hpp"
#include "sluice/sim/prescribed_motion.hpp"
#include "sluice/sim/rigid_bodies.hpp"

namespace sluice {
namespace {

io::CaseConfig case_with(const std::string& bodies, bool fluid) {
  std::string text =
      "dimension: 3\nspacing: 0.05\ndomain: {min: [0, 0, 0], max: [1, 1, 1]}\nend_time: 1\n"
      "output_interval: 0.1\nwalls:\n  - {type: tank, min: [0, 0, 0], max: [1, 1, 1], open: "
      "[z+]}\nbodies:\n" +
      bodies;
  if (fluid)
    text += "fluid:\n  blocks:\n    - {min: [0, 0, 0], max: [1, 1, 0.2]}\nmodel:\n  name: wcsph\n";
  return io::parse_case(text, "t.yaml");
}

TEST(RigidBodies, BoxMassAndFluidParticlesUnderTheSurface) {
  const RigidBodies bodies(case_with(
      "  - {shape: box, size: [0.2, 0.3, 0.4], density: 500, position: [0.5, 0.5, 0.5]}\n", true));
  ASSERT_EQ(bodies.count(), 1u);
  const RigidBody& s = bodies.state(0);
  EXPECT_NEAR(s.mass, 500 * 0.2 * 0.3 * 0.4, 1e-12);
  EXPECT_NEAR(s.principal_inertia[2], s.mass * (0.04 + 0.09) / 12, 1e-12);
  // The outermost particles the fluid sees lie dx/2 under each face.
  Vec3 extent = Vec3::Zero();
  for (const BodyPoint& p : bodies.points_under_surface(3))
    extent = extent.cwiseMax(p.local.cwiseAbs());
  EXPECT_NEAR(extent[0], 0.1 - 0.025, 1e-12);
  EXPECT_NEAR(extent[2], 0.2 - 0.025, 1e-12);
  // Five closed sides of the tank join the body in the contact system.
  EXPECT_EQ(bodies.system().bodies().size(), 6u);
}

TEST(RigidBodies, WithoutFluidThePointsAreTheSurface) {
  const RigidBodies bodies(case_with(
      "  - {shape: sphere, radius: 0.1, density: 1000, position: [0.5, 0.5, 0.5]}\n", false));
  for (const BodyPoint& p : bodies.surface_points()) EXPECT_NEAR(p.local.norm(), 0.1, 1e-12);
}

TEST(RigidBodies, OccupiesInsideAndWithinClearance) {
  const RigidBodies bodies(
      case_with("  - {shape: box, size: [0.2, 0.2, 0.2], density: 500, position: [0.5, 0.5, 0.5], "
                "rotation_deg: [0, 0, 45]}\n",
                false));
  EXPECT_TRUE(bodies.occupies(Vec3(0.5, 0.5, 0.5), 0));
  EXPECT_TRUE(bodies.occupies(Vec3(0.5 + 0.13, 0.5, 0.5), 0));        // inside a turned corner
  EXPECT_FALSE(bodies.occupies(Vec3(0.5 + 0.1, 0.5 + 0.1, 0.5), 0));  // outside a turned face
  EXPECT_FALSE(bodies.occupies(Vec3(0.5, 0.5, 0.62), 0.01));
  // The clearance counts from the face, not from its nearest particle (0.041 m away).
  EXPECT_TRUE(bodies.occupies(Vec3(0.5, 0.5, 0.62), 0.025));
  EXPECT_TRUE(bodies.occupies(Vec3(0.5, 0.5, 0.6), 0.001));  // on the face, between particles
}

TEST(RigidBodies, PrescribedBodyIsPlacedAtItsPose) {
  const RigidBodies bodies(case_with(
      "  - {shape: box, size: [0.2, 0.2, 0.2], density: 500, position: [0.3, 0.5, 0.5], "
      "velocity: [0.5, 0, 0], motion: prescribed, prescribed: {type: constant_velocity}}\n",
      false));
  EXPECT_TRUE(bodies.system().bodies()[0].fixed);
  EXPECT_EQ(bodies.state(0).velocity, Vec3(0.5, 0, 0));
}

// A ramped constant velocity starts from rest, reaches the set speed at ramp_time along
// (1 - cos(pi t / T)) / 2, and from then on lies T/2 of travel behind the unramped motion.
TEST(RigidBodies, RampedConstantVelocityStartsFromRest) {
  const io::CaseConfig c = case_with(
      "  - {shape: box, size: [0.2, 0.2, 0.2], density: 500, position: [0.3, 0.5, 0.5], "
      "velocity: [0.5, 0, 0], motion: prescribed,\n"
      "     prescribed: {type: constant_velocity, ramp_time: 0.4}}\n",
      false);
  const io::BodyConfig& body = c.bodies[0];
  EXPECT_EQ(prescribed_pose(body, 0).velocity, Vec3::Zero());
  EXPECT_NEAR(prescribed_pose(body, 0.2).velocity[0], 0.25, 1e-15);
  EXPECT_NEAR(prescribed_pose(body, 0.4).velocity[0], 0.5, 1e-15);
  EXPECT_NEAR(prescribed_pose(body, 1.0).position[0], 0.3 + 0.5 * (1.0 - 0.2), 1e-15);
  // The position is the integral of the velocity: a central difference matches it.
  for (const double t : {0.05, 0.2, 0.39, 0.41}) {
    const double h = 1e-6;
    const double slope =
        (prescribed_pose(body, t + h).position[0] - prescribed_pose(body, t - h).position[0]) /
        (2 * h);
    EXPECT_NEAR(slope, prescribed_pose(body, t).velocity[0], 1e-8) << t;
  }
  const RigidBodies bodies(c);
  EXPECT_EQ(bodies.state(0).velocity, Vec3::Zero());
}

// Distance queries on a body turned 45 degrees about z, and on the tank's walls.
TEST(RigidBodies, NearestSurfaceOfABodyAndOfTheWalls) {
  const RigidBodies bodies(
      case_with("  - {shape: box, size: [0.2, 0.2, 0.2], density: 500, position: [0.5, 0.5, 0.5], "
                "rotation_deg: [0, 0, 45]}\n",
                true));
  // Along the turned face normal (1, 1, 0)/sqrt 2, 0.05 beyond the face.
  const Vec3 n = Vec3(1, 1, 0).normalized();
  const Vec3 x = Vec3(0.5, 0.5, 0.5) + 0.15 * n;
  const SurfacePoint p = bodies.nearest_on_body(0, x);
  EXPECT_NEAR(p.distance, 0.05, 1e-12);
  EXPECT_NEAR((p.normal - n).norm(), 0, 1e-12);
  EXPECT_NEAR((p.closest - (Vec3(0.5, 0.5, 0.5) + 0.1 * n)).norm(), 0, 1e-12);
  EXPECT_NEAR(bodies.nearest_on_body(0, Vec3(0.5, 0.5, 0.52)).distance, -0.08, 1e-12);
  // The tank [0, 1]^3, open at the top: the floor is nearest at z = 0.1, not the open lid.
  const SurfacePoint floor = bodies.nearest_on_walls(Vec3(0.5, 0.4, 0.1));
  EXPECT_NEAR(floor.distance, 0.1, 1e-12);
  EXPECT_EQ(floor.normal, Vec3::UnitZ());
  EXPECT_NEAR(bodies.nearest_on_walls(Vec3(0.5, 0.5, 0.97)).distance, 0.5, 1e-12);
  EXPECT_NEAR(bodies.nearest_on_walls(Vec3(-0.02, 0.5, 0.5)).distance, -0.02, 1e-12);
  // Surface samples with their normals and areas: a closed surface's n dA add up to zero.
  const auto normals = bodies.surface_normals();
  const auto areas = bodies.surface_areas();
  ASSERT_EQ(normals.size(), bodies.surface_points().size());
  Vec3 sum = Vec3::Zero();
  double area = 0;
  for (std::size_t k = 0; k < normals.size(); ++k) {
    sum += areas[k] * normals[k];
    area += areas[k];
  }
  EXPECT_NEAR(area, 6 * 0.04, 1e-12);
  EXPECT_NEAR(sum.norm(), 0, 1e-12);
}

// The grid's projection moves the bodies through their joined mobility W (projection scheme).
// A box resting on the floor keeps its contact pairs' normal velocities there, as a joint
// would: W answers a downward push with nothing and a push along the floor, at its centre of
// mass, as a free body would; a contact lets go where it would pull. For the held loads, which
// have no such rows, a body held by a contact is immobile.
TEST(RigidBodies, ABoxOnTheFloorMovesAlongItButNotIntoIt) {
  RigidBodies bodies(
      case_with("  - {shape: box, size: [0.2, 0.2, 0.2], density: 500, position: [0.5, 0.5, "
                "0.101]}\n",
                false));
  for (int step = 0; step < 200 && bodies.system().contact_force()[0].norm() == 0; ++step)
    bodies.system().advance(1e-3);
  ASSERT_GT(bodies.system().contact_force()[0].norm(), 0) << "the box never reached the floor";
  ASSERT_FALSE(bodies.system().contact().contacts().contacts().empty());
  const double mass = bodies.state(0).mass;
  const Eigen::MatrixXd w = bodies.joined_mobility();
  ASSERT_EQ(w.rows(), 6);
  Eigen::VectorXd push = Eigen::VectorXd::Zero(6);
  push[2] = -1;  // N s, down into the floor
  EXPECT_LT((w * push).norm(), 1e-9 / mass);
  push.setZero();
  push[0] = 1;  // along the floor
  Eigen::VectorXd free = Eigen::VectorXd::Zero(6);
  free[0] = 1 / mass;
  EXPECT_LT((w * push - free).norm(), 1e-9 / mass);
  // Given the impulse it will answer, a contact that would have to pull the box onto the floor
  // lets go: pushed up, the box rises as a free body; pushed down, the floor still holds it.
  push.setZero();
  push[2] = 1;
  Eigen::VectorXd up = Eigen::VectorXd::Zero(6);
  up[2] = 1 / mass;
  EXPECT_LT((bodies.joined_mobility(push) * push - up).norm(), 1e-9 / mass);
  EXPECT_LT((bodies.joined_mobility(-push) * push).norm(), 1e-9 / mass);
  const BodyMobility held = bodies.mobility(0);
  EXPECT_EQ(held.inverse_mass, Eigen::Matrix3d::Zero());
  EXPECT_EQ(held.inverse_inertia, Eigen::Matrix3d::Zero());
}

}  // namespace
}  // namespace sluice
