// The fluid's force on the bodies as the integral of the pressure over their faces, from the
// pressure of their boundary particles (the first layer, dx/2 under the surface). Each surface
// sample of a body (its contact particles: place, outward normal and area) takes the pressure
// of the nearest boundary particle, carried to the sample along the local hydrostatic
// gradient, p_s = p_k + rho (g - a_k) . (x_s - x_k), and pushes with -p_s n_s A_s on that
// particle. Summing particle forces instead would give only the local pressure gradient: the
// MPS gradient measures pressure against its neighbourhood minimum, not its level.
#pragma once

#include <vector>

#include "sluice/coupling/body_geometry.hpp"
#include "sluice/coupling/body_points.hpp"

namespace sluice {

class BodySurfacePressure {
 public:
  BodySurfacePressure() = default;
  // `boundary[k]` says whether body point k is a boundary particle.
  BodySurfacePressure(const BodyGeometry& bodies, const BodyPoints& points,
                      const std::vector<bool>& boundary);

  // Adds each sample's force to its body point. `pressure[k]` is the pressure of body point k
  // (wet[k] false: no fluid reaches it, no force); `acceleration[k]` its acceleration.
  void add_forces(const std::vector<double>& pressure, const std::vector<bool>& wet,
                  const std::vector<Vec3>& acceleration, const Vec3& gravity, double density,
                  bool keep_negative, const std::vector<BodyKinematics>& motion,
                  std::vector<Vec3>& force) const;

  std::size_t sample_count() const { return samples_.size(); }

 private:
  struct Sample {
    std::size_t point = 0;  // the body point whose pressure it takes
    std::size_t body = 0;
    Vec3 offset = Vec3::Zero();  // sample minus point, in the body's principal frame
    Vec3 normal = Vec3::Zero();  // outward, principal frame
    double area = 0;
  };
  std::vector<Sample> samples_;
};

}  // namespace sluice
