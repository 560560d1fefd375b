// Points fixed in the bodies (a particle fluid's body particles): where they are and how they
// move, from the bodies' kinematics, and the wrench on each body from forces on its points.
#pragma once

#include <cstdint>
#include <vector>

#include "sluice/coupling/body_motion.hpp"

namespace sluice {

// A body's kinematics as rigid_point.hpp reads them (kBodyMotionReals reals), for one body or
// for each of them in a row.
void pack_body_motion(const BodyKinematics& m, double* out);
std::vector<double> pack_body_motion(const std::vector<BodyKinematics>& motion);

class BodyPoints {
 public:
  BodyPoints() = default;
  explicit BodyPoints(std::vector<BodyPoint> points) : points_(std::move(points)) {}

  std::size_t size() const { return points_.size(); }
  const BodyPoint& operator[](std::size_t k) const { return points_[k]; }

  // World position, velocity and acceleration of point k for its body's kinematics
  // (rigid_point.hpp, as a device run places them).
  Vec3 position(std::size_t k, const std::vector<BodyKinematics>& motion) const;
  Vec3 velocity(std::size_t k, const std::vector<BodyKinematics>& motion) const;
  Vec3 acceleration(std::size_t k, const std::vector<BodyKinematics>& motion) const;

  // The force and moment about the centre of mass on each of `bodies` bodies, from a force on
  // every point, summed in the points' order (point_wrench.hpp, as a device run sums them).
  std::vector<Wrench> loads(const std::vector<Vec3>& point_force,
                            const std::vector<BodyKinematics>& motion, std::size_t bodies) const;
  // Where each of `bodies` bodies' points start, and the end as the last entry (bodies + 1
  // entries): the points come grouped by body, in the bodies' order. Throws std::logic_error
  // when they do not.
  std::vector<std::uint32_t> first_of_each_body(std::size_t bodies) const;

 private:
  std::vector<BodyPoint> points_;
};

}  // namespace sluice
