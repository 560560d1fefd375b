// Points fixed in the bodies (a particle fluid's body particles): where they are and how they
// move, from the bodies' kinematics, and the wrench on each body from forces on its points.
#pragma once

#include <vector>

#include "sluice/coupling/body_motion.hpp"

namespace sluice {

class BodyPoints {
 public:
  BodyPoints() = default;
  explicit BodyPoints(std::vector<BodyPoint> points) : points_(std::move(points)) {}

  std::size_t size() const { return points_.size(); }
  const BodyPoint& operator[](std::size_t k) const { return points_[k]; }

  // World position, velocity and acceleration of point k for its body's kinematics.
  Vec3 position(std::size_t k, const std::vector<BodyKinematics>& motion) const;
  Vec3 velocity(std::size_t k, const std::vector<BodyKinematics>& motion) const;
  Vec3 acceleration(std::size_t k, const std::vector<BodyKinematics>& motion) const;

  // The force and moment about the centre of mass on each of `bodies` bodies, from a force on
  // every point, summed in the points' order.
  std::vector<Wrench> loads(const std::vector<Vec3>& point_force,
                            const std::vector<BodyKinematics>& motion, std::size_t bodies) const;

 private:
  std::vector<BodyPoint> points_;
};

}  // namespace sluice
