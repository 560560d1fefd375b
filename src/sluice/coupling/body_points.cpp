#include "sluice/coupling/body_points.hpp"

namespace sluice {

Vec3 BodyPoints::position(std::size_t k, const std::vector<BodyKinematics>& motion) const {
  const BodyKinematics& m = motion[points_[k].body];
  return m.position + m.orientation * points_[k].local;
}

Vec3 BodyPoints::velocity(std::size_t k, const std::vector<BodyKinematics>& motion) const {
  const BodyKinematics& m = motion[points_[k].body];
  return m.velocity + m.angular_velocity.cross(m.orientation * points_[k].local);
}

Vec3 BodyPoints::acceleration(std::size_t k, const std::vector<BodyKinematics>& motion) const {
  const BodyKinematics& m = motion[points_[k].body];
  const Vec3 r = m.orientation * points_[k].local;
  const Vec3& w = m.angular_velocity;
  return m.acceleration + m.angular_acceleration.cross(r) + w.cross(w.cross(r));
}

std::vector<Wrench> BodyPoints::loads(const std::vector<Vec3>& point_force,
                                      const std::vector<BodyKinematics>& motion,
                                      std::size_t bodies) const {
  std::vector<Wrench> out(bodies);
  for (std::size_t k = 0; k < points_.size(); ++k) {
    const std::size_t b = points_[k].body;
    out[b].force += point_force[k];
    out[b].moment += (position(k, motion) - motion[b].position).cross(point_force[k]);
  }
  return out;
}

}  // namespace sluice
