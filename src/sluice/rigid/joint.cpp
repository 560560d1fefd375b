#include "sluice/rigid/joint.hpp"

#include <cmath>

namespace sluice {

namespace {

constexpr std::size_t kWorld = ConstraintRow::kWorld;

// A body's pose, or the world's (at the origin, unturned).
struct Pose {
  Vec3 position = Vec3::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

Pose pose_of(const std::vector<SystemBody>& bodies, std::size_t b) {
  if (b == kWorld) return {};
  return {bodies[b].state.position, bodies[b].state.orientation};
}

// Two unit vectors completing `axis` to an orthonormal frame.
void perpendiculars(const Vec3& axis, Vec3& n1, Vec3& n2) {
  const Vec3 a = std::abs(axis.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
  n1 = (a - a.dot(axis) * axis).normalized();
  n2 = axis.cross(n1);
}

// The rotation that takes b's target orientation (a's turned by `relative`) to b's own, as a
// rotation vector in the world (small: angle times axis).
Vec3 orientation_error(const Joint& j, const Pose& a, const Pose& b) {
  Eigen::Quaterniond error = b.orientation * (a.orientation * j.relative).conjugate();
  if (error.w() < 0) error.coeffs() *= -1;
  const double s = error.vec().norm();
  if (s < 1e-12) return 2 * error.vec();
  return 2 * std::atan2(s, error.w()) * error.vec() / s;
}

// A row along world direction e between the anchors: e . (v_b + w_b x r_b - v_a - w_a x r_a).
ConstraintRow point_row(const Joint& j, const Vec3& e, const Vec3& ra, const Vec3& rb) {
  ConstraintRow row;
  row.a = j.a;
  row.b = j.b;
  row.linear_a = -e;
  row.angular_a = -ra.cross(e);
  row.linear_b = e;
  row.angular_b = rb.cross(e);
  return row;
}

// A row on the relative angular velocity about world direction e: e . (w_b - w_a).
ConstraintRow turn_row(const Joint& j, const Vec3& e) {
  ConstraintRow row;
  row.a = j.a;
  row.b = j.b;
  row.angular_a = -e;
  row.angular_b = e;
  return row;
}

}  // namespace

Joint make_joint(JointType type, std::size_t a, std::size_t b,
                 const std::vector<SystemBody>& bodies, const Vec3& anchor, const Vec3& axis) {
  Joint j;
  j.type = type;
  j.a = a;
  j.b = b;
  const Pose pa = pose_of(bodies, a), pb = pose_of(bodies, b);
  j.anchor_a = pa.orientation.conjugate() * (anchor - pa.position);
  j.anchor_b = pb.orientation.conjugate() * (anchor - pb.position);
  Vec3 n1, n2;
  perpendiculars(axis, n1, n2);
  j.axis_a = pa.orientation.conjugate() * axis;
  j.normal_a1 = pa.orientation.conjugate() * n1;
  j.normal_a2 = pa.orientation.conjugate() * n2;
  j.normal_b1 = pb.orientation.conjugate() * n1;
  j.normal_b2 = pb.orientation.conjugate() * n2;
  j.relative = pa.orientation.conjugate() * pb.orientation;
  return j;
}

void add_joint_rows(const Joint& j, const std::vector<SystemBody>& bodies, double h,
                    double stabilisation, RowGroup& rows) {
  const Pose pa = pose_of(bodies, j.a), pb = pose_of(bodies, j.b);
  const Vec3 ra = pa.orientation * j.anchor_a, rb = pb.orientation * j.anchor_b;
  const Vec3 gap = (pb.position + rb) - (pa.position + ra);  // the anchors' separation
  const double back = stabilisation / h;                     // velocity per unit of error
  auto push = [&](ConstraintRow row, double error) {
    row.bias = -back * error;
    rows.add_row(row);
  };
  const Vec3 axis = pa.orientation * j.axis_a;
  if (j.type == JointType::kPrismatic) {
    // The anchor of b stays on a's axis: no relative motion along a's normals.
    for (const Vec3& local : {j.normal_a1, j.normal_a2}) {
      const Vec3 n = pa.orientation * local;
      ConstraintRow row = point_row(j, n, ra, rb);
      row.angular_a += n.cross(gap);  // a's normal turns with a
      push(row, n.dot(gap));
    }
  } else {
    for (int k = 0; k < 3; ++k) push(point_row(j, Vec3::Unit(k), ra, rb), gap[k]);
  }
  if (j.type == JointType::kFixed || j.type == JointType::kPrismatic) {
    const Vec3 error = orientation_error(j, pa, pb);
    for (int k = 0; k < 3; ++k) push(turn_row(j, Vec3::Unit(k)), error[k]);
  }
  if (j.type == JointType::kRevolute) {
    // a's axis stays perpendicular to b's normals: (u . w)' = (w_a - w_b) . (u x w).
    for (const Vec3& local : {j.normal_b1, j.normal_b2}) {
      const Vec3 w = pb.orientation * local;
      ConstraintRow row;
      row.a = j.a;
      row.b = j.b;
      row.angular_a = axis.cross(w);
      row.angular_b = -axis.cross(w);
      push(row, axis.dot(w));
    }
    if (j.motor_speed) {
      ConstraintRow motor = turn_row(j, axis);
      motor.bias = *j.motor_speed;
      motor.lower = -j.motor_torque * h;
      motor.upper = j.motor_torque * h;
      rows.add_row(motor);
    }
  }
}

JointError joint_error(const Joint& j, const std::vector<SystemBody>& bodies) {
  const Pose pa = pose_of(bodies, j.a), pb = pose_of(bodies, j.b);
  const Vec3 gap =
      (pb.position + pb.orientation * j.anchor_b) - (pa.position + pa.orientation * j.anchor_a);
  JointError e;
  const Vec3 axis = pa.orientation * j.axis_a;
  if (j.type == JointType::kPrismatic) {
    e.distance = (gap - gap.dot(axis) * axis).norm();
  } else {
    e.distance = gap.norm();
  }
  if (j.type == JointType::kFixed || j.type == JointType::kPrismatic) {
    e.angle = orientation_error(j, pa, pb).norm();
  } else if (j.type == JointType::kRevolute) {
    const Vec3 axis_b = pb.orientation * j.normal_b1.cross(j.normal_b2);  // b's copy of the axis
    e.angle = std::acos(std::clamp(axis.dot(axis_b), -1.0, 1.0));
  }
  return e;
}

}  // namespace sluice
