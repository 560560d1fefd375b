// A rigid body's dynamic state. Orientation is a unit quaternion from the body's principal
// frame to the world; the rotational state is the world-frame angular momentum, which the
// integrator conserves exactly in free flight (rigid/rigid_integrator.hpp).
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <string>

#include "sluice/core/state_archive.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

struct RigidBody {
  std::string name;
  double mass = 1;
  Vec3 principal_inertia = Vec3::Ones();  // moments about the principal axes through the COM

  Vec3 position = Vec3::Zero();                                     // centre of mass, world frame
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // principal -> world
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_momentum = Vec3::Zero();  // world frame

  // Degrees of freedom held at zero velocity: translation along x, y, z; rotation about x, y, z
  // (world axes). A 2D body in the x-z plane locks translation y and rotation about x and z.
  std::array<bool, 3> locked_translation{};
  std::array<bool, 3> locked_rotation{};

  Eigen::Matrix3d rotation() const { return orientation.toRotationMatrix(); }

  // World-frame inertia tensor and its inverse at the current orientation.
  Eigen::Matrix3d world_inertia() const {
    const Eigen::Matrix3d r = rotation();
    return r * principal_inertia.asDiagonal() * r.transpose();
  }
  Eigen::Matrix3d inverse_world_inertia() const {
    const Eigen::Matrix3d r = rotation();
    return r * principal_inertia.cwiseInverse().asDiagonal() * r.transpose();
  }

  Vec3 angular_velocity() const { return inverse_world_inertia() * angular_momentum; }

  // Velocity of the body's material point at world position x.
  Vec3 velocity_at(const Vec3& x) const {
    return velocity + angular_velocity().cross(x - position);
  }

  double kinetic_energy() const {
    return 0.5 * mass * velocity.squaredNorm() + 0.5 * angular_momentum.dot(angular_velocity());
  }

  // Applies the locks: zero locked velocities and locked angular-velocity components.
  void enforce_locks();

  // Checkpoints: the motion (mass, inertia and locks come from the case).
  void archive_state(StateArchive& a) { a(position, orientation, velocity, angular_momentum); }
};

}  // namespace sluice
