// Joints between two rigid bodies, or a body and the world, as velocity-level equality rows
// for the cone complementarity step (ccp/): each row asks the relative motion the joint forbids
// to vanish, with the position error it has drifted to taken back over `stabilisation` of a
// step (Baumgarte: 1 closes it in one step). Spherical: the anchor points meet. Revolute: and
// the axes stay aligned; a motor holds the relative angular speed about the axis (within its
// torque). Prismatic: the relative orientation is kept and the anchor slides along the axis.
// Fixed: both.
#pragma once

#include <Eigen/Geometry>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "sluice/ccp/row_group.hpp"
#include "sluice/rigid/body_interaction.hpp"

namespace sluice {

enum class JointType { kFixed, kRevolute, kPrismatic, kSpherical };

struct Joint {
  std::string name;
  JointType type = JointType::kSpherical;
  std::size_t a = ConstraintRow::kWorld, b = ConstraintRow::kWorld;  // system bodies
  // The anchor and axis in each body's principal frame, about its centre of mass (the world:
  // world coordinates). Unit axes.
  Vec3 anchor_a = Vec3::Zero(), anchor_b = Vec3::Zero();
  Vec3 axis_a = Vec3::UnitZ();
  // Two unit vectors perpendicular to the axis, in a's frame and in b's.
  Vec3 normal_a1 = Vec3::UnitX(), normal_a2 = Vec3::UnitY();
  Vec3 normal_b1 = Vec3::UnitX(), normal_b2 = Vec3::UnitY();
  // Fixed, prismatic: b's orientation in a's frame at the start, q_a^-1 q_b.
  Eigen::Quaterniond relative = Eigen::Quaterniond::Identity();
  // Revolute: b turns about the axis relative to a at this speed [rad/s], with at most
  // motor_torque [N m].
  std::optional<double> motor_speed;
  double motor_torque = std::numeric_limits<double>::infinity();
};

// A joint between bodies a and b (either may be ConstraintRow::kWorld) at a world anchor with
// a world axis (unit), at the bodies' present poses.
Joint make_joint(JointType type, std::size_t a, std::size_t b,
                 const std::vector<SystemBody>& bodies, const Vec3& anchor, const Vec3& axis);

// Appends the joint's rows for a step of h.
void add_joint_rows(const Joint& joint, const std::vector<SystemBody>& bodies, double h,
                    double stabilisation, RowGroup& rows);

// The joint's position error: how far apart the anchors are [m] and how far the axes (or,
// fixed and prismatic, the orientations) have turned from each other [rad].
struct JointError {
  double distance = 0, angle = 0;
};
JointError joint_error(const Joint& joint, const std::vector<SystemBody>& bodies);

}  // namespace sluice
