// How the bodies move, as a fluid sees them, and the points a particle fluid fixes in them.
#pragma once

#include <Eigen/Geometry>
#include <cstddef>

#include "sluice/core/state_archive.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

// A body's pose and motion at one time: its centre of mass, principal frame, velocities, and
// the accelerations of the last step (moving walls feel them in their pressure).
struct BodyKinematics {
  Vec3 position = Vec3::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // principal -> world
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();
  Vec3 acceleration = Vec3::Zero();
  Vec3 angular_acceleration = Vec3::Zero();
};

// A point fixed in a body: its body and its place in the body's principal frame, relative to
// the centre of mass.
struct BodyPoint {
  std::size_t body = 0;
  Vec3 local = Vec3::Zero();
};

// The force and moment (about the centre of mass) on a body.
struct Wrench {
  Vec3 force = Vec3::Zero();
  Vec3 moment = Vec3::Zero();
};

inline void archive_state(StateArchive& a, BodyKinematics& k) {
  a(k.position, k.orientation, k.velocity, k.angular_velocity, k.acceleration,
    k.angular_acceleration);
}
inline void archive_state(StateArchive& a, Wrench& w) {
  a(w.force, w.moment);
}

}  // namespace sluice
