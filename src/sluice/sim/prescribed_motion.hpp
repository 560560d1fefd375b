// Prescribed body motion from a case file: the pose of the shape's origin and its velocities at
// any time, for a constant velocity, a sinusoid about the initial pose, or a pose table.
#pragma once

#include <Eigen/Geometry>

#include "sluice/io/body_config.hpp"

namespace sluice {

struct ShapePose {
  Vec3 position = Vec3::Zero();  // of the shape's origin
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();
};

// Rotation by angles about the fixed x, then y, then z axes (radians).
Eigen::Quaterniond rotation_from_angles(const Vec3& angles);

// The world angular velocity of rotation_from_angles(angles) while the angles change at `rates`.
Vec3 angular_velocity_from_rates(const Vec3& angles, const Vec3& rates);

// What a wave paddle's active absorption adds to its signal's displacement at the still water
// line [m] and to its velocity there [m/s] (sim/paddle_absorber.hpp).
struct PaddleCorrection {
  double displacement = 0;
  double velocity = 0;
};

// The pose at `time` of a body given by `body` (its motion must be prescribed): the angles
// move with time, and the angular velocity is that of the turning they make. A table is
// interpolated linearly and held at its first and last rows. A wavemaker's displacement is
// its signal's plus `correction`.
ShapePose prescribed_pose(const io::BodyConfig& body, double time,
                          const PaddleCorrection& correction = {});

}  // namespace sluice
