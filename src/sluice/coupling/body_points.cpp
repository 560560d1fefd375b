#include "sluice/coupling/body_points.hpp"

#include <algorithm>
#include <stdexcept>

#include "sluice/coupling/point_wrench.hpp"
#include "sluice/coupling/rigid_point.hpp"

namespace sluice {

void pack_body_motion(const BodyKinematics& m, double* out) {
  const Vec3* vectors[] = {&m.velocity, &m.angular_velocity, &m.acceleration,
                           &m.angular_acceleration};
  for (int a = 0; a < 3; ++a) out[a] = m.position[a];
  for (int a = 0; a < 4; ++a) out[3 + a] = m.orientation.coeffs()[a];  // x, y, z, w
  for (int v = 0; v < 4; ++v) {
    for (int a = 0; a < 3; ++a) out[7 + 3 * v + a] = (*vectors[v])[a];
  }
}

std::vector<double> pack_body_motion(const std::vector<BodyKinematics>& motion) {
  std::vector<double> out(kBodyMotionReals * motion.size());
  for (std::size_t b = 0; b < motion.size(); ++b)
    pack_body_motion(motion[b], &out[kBodyMotionReals * b]);
  return out;
}

namespace {

// One of rigid_point.hpp's functions for point k of a body moving by `m`.
template <class PointFunction>
Vec3 rigid_point(PointFunction f, const BodyKinematics& m, const Vec3& local) {
  double body[kBodyMotionReals];
  pack_body_motion(m, body);
  Vec3 out;
  f(body, local.data(), out.data());
  return out;
}

}  // namespace

Vec3 BodyPoints::position(std::size_t k, const std::vector<BodyKinematics>& motion) const {
  return rigid_point(rigid_point_position, motion[points_[k].body], points_[k].local);
}

Vec3 BodyPoints::velocity(std::size_t k, const std::vector<BodyKinematics>& motion) const {
  return rigid_point(rigid_point_velocity, motion[points_[k].body], points_[k].local);
}

Vec3 BodyPoints::acceleration(std::size_t k, const std::vector<BodyKinematics>& motion) const {
  return rigid_point(rigid_point_acceleration, motion[points_[k].body], points_[k].local);
}

std::vector<Wrench> BodyPoints::loads(const std::vector<Vec3>& point_force,
                                      const std::vector<BodyKinematics>& motion,
                                      std::size_t bodies) const {
  std::vector<Wrench> out(bodies);
  if (points_.empty()) return out;
  const std::vector<std::uint32_t> first = first_of_each_body(bodies);
  std::vector<Vec3> where(points_.size());
  for (std::size_t k = 0; k < points_.size(); ++k) where[k] = position(k, motion);
  for (std::size_t b = 0; b < bodies; ++b) {
    double wrench[6];
    sum_point_wrenches(where.front().data(), point_force.front().data(), first[b], first[b + 1],
                       motion[b].position.data(), wrench);
    out[b].force = Vec3(wrench[0], wrench[1], wrench[2]);
    out[b].moment = Vec3(wrench[3], wrench[4], wrench[5]);
  }
  return out;
}

std::vector<std::uint32_t> BodyPoints::first_of_each_body(std::size_t bodies) const {
  std::vector<std::uint32_t> first(bodies + 1, static_cast<std::uint32_t>(points_.size()));
  for (std::size_t k = points_.size(); k-- > 0;) {
    const std::size_t b = points_[k].body;
    if (b >= bodies || (k + 1 < points_.size() && points_[k + 1].body < b)) {
      throw std::logic_error(
          "BodyPoints: the points are not grouped by body in order, or name a body past the last");
    }
    first[b] = static_cast<std::uint32_t>(k);
  }
  // A body without points starts where the next one does.
  for (std::size_t b = bodies; b-- > 0;) first[b] = std::min(first[b], first[b + 1]);
  return first;
}

}  // namespace sluice
