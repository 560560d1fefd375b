// The rigid-body integrator: exact for constant forces, angular momentum conserved to
// round-off and energy bounded in free tumbling, locks respected.
#include <gtest/gtest.h>

#include <cmath>

#include "sluice/rigid/rigid_integrator.hpp"

namespace sluice {
namespace {

TEST(RigidIntegrator, ConstantForceGivesTheExactParabola) {
  RigidBody body;
  body.mass = 2.0;
  body.velocity = Vec3(1, 0, 3);
  const Vec3 gravity(0, 0, -9.81);
  Vec3 force = body.mass * gravity, torque = Vec3::Zero();
  const double dt = 1e-3;
  for (int k = 0; k < 1000; ++k) {
    step_rigid(body, force, torque, dt,
               [&](const RigidBody& b, Vec3& f, Vec3&) { f = b.mass * gravity; });
  }
  const double t = 1.0;
  EXPECT_NEAR((body.position - (Vec3(1, 0, 3) * t + 0.5 * gravity * t * t)).norm(), 0, 1e-10);
  EXPECT_NEAR((body.velocity - (Vec3(1, 0, 3) + gravity * t)).norm(), 0, 1e-10);
}

TEST(RigidIntegrator, FreeTumblingKeepsAngularMomentumAndEnergy) {
  RigidBody body;
  body.principal_inertia = Vec3(1.0, 2.0, 3.0);  // asymmetric: rotation about axis 2 is unstable
  body.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()));
  body.angular_momentum = body.world_inertia() * Vec3(0.1, 2.0, 0.05);  // near the unstable axis
  const Vec3 momentum = body.angular_momentum;
  const double energy = body.kinetic_energy();
  double worst_energy_error = 0;
  Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
  for (int k = 0; k < 100000; ++k) {
    step_rigid(body, force, torque, 1e-3, [](const RigidBody&, Vec3&, Vec3&) {});
    worst_energy_error = std::max(worst_energy_error, std::abs(body.kinetic_energy() / energy - 1));
  }
  // Round-off only: 5e5 exact sub-rotations at about 1e-16 each.
  EXPECT_LT((body.angular_momentum - momentum).norm() / momentum.norm(), 1e-10);
  EXPECT_LT(worst_energy_error, 1e-4) << "energy error over 100 s of tumbling";
  EXPECT_NEAR(body.orientation.norm(), 1.0, 1e-12);
  // The body really tumbled: the intermediate axis is unstable, so it flips.
  const Vec3 axis2 = body.orientation * Vec3::UnitY();
  EXPECT_LT(axis2.dot(momentum.normalized()), 0.99);
}

TEST(RigidIntegrator, TorqueAboutAPrincipalAxisSpinsUpLinearly) {
  RigidBody body;
  body.principal_inertia = Vec3(2, 3, 4);
  Vec3 force = Vec3::Zero(), torque(0, 0, 8.0);
  for (int k = 0; k < 500; ++k) {
    step_rigid(body, force, torque, 1e-3,
               [](const RigidBody&, Vec3&, Vec3& t) { t = Vec3(0, 0, 8.0); });
  }
  EXPECT_NEAR(body.angular_velocity()[2], 8.0 * 0.5 / 4.0, 1e-12);
  // angle = alpha t^2 / 2 = (8 / 4) 0.25 / 2
  const double angle = 2 * std::atan2(body.orientation.vec().norm(), body.orientation.w());
  EXPECT_NEAR(angle, 0.25, 1e-9);
}

TEST(RigidIntegrator, LockedDegreesOfFreedomStayStill) {
  RigidBody body;
  body.principal_inertia = Vec3(1, 2, 3);
  body.locked_translation = {false, true, false};
  body.locked_rotation = {true, false, true};
  Vec3 force(1, 1, 1), torque(1, 1, 1);
  for (int k = 0; k < 100; ++k) {
    step_rigid(body, force, torque, 1e-2, [](const RigidBody&, Vec3& f, Vec3& t) {
      f = Vec3(1, 1, 1);
      t = Vec3(1, 1, 1);
    });
  }
  EXPECT_EQ(body.position[1], 0.0);
  EXPECT_NEAR(body.angular_velocity()[0], 0.0, 1e-12);
  EXPECT_NEAR(body.angular_velocity()[2], 0.0, 1e-12);
  EXPECT_GT(body.angular_velocity()[1], 0.0);
}

}  // namespace
}  // namespace sluice
