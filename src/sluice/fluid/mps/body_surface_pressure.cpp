#include "sluice/fluid/mps/body_surface_pressure.hpp"

#include <algorithm>
#include <limits>

namespace sluice {

BodySurfacePressure::BodySurfacePressure(const BodyGeometry& bodies, const BodyPoints& points,
                                         const std::vector<bool>& boundary) {
  const std::vector<BodyPoint> surface = bodies.surface_points();
  const std::vector<Vec3> normals = bodies.surface_normals();
  const std::vector<double> areas = bodies.surface_areas();
  // The boundary points of each body, for the nearest-point search.
  std::vector<std::vector<std::size_t>> of_body(bodies.body_count());
  for (std::size_t k = 0; k < points.size(); ++k) {
    if (boundary[k]) of_body[points[k].body].push_back(k);
  }
  samples_.reserve(surface.size());
  for (std::size_t s = 0; s < surface.size(); ++s) {
    const std::size_t b = surface[s].body;
    double best = std::numeric_limits<double>::infinity();
    std::size_t nearest = 0;
    for (std::size_t k : of_body[b]) {
      const double d2 = (points[k].local - surface[s].local).squaredNorm();
      if (d2 < best) {
        best = d2;
        nearest = k;
      }
    }
    if (of_body[b].empty()) continue;  // a body too thin for particles feels no pressure
    samples_.push_back(
        {nearest, b, surface[s].local - points[nearest].local, normals[s], areas[s]});
  }
}

void BodySurfacePressure::add_forces(const std::vector<double>& pressure,
                                     const std::vector<bool>& wet,
                                     const std::vector<Vec3>& acceleration, const Vec3& gravity,
                                     double density, bool keep_negative,
                                     const std::vector<BodyKinematics>& motion,
                                     std::vector<Vec3>& force) const {
  for (const Sample& s : samples_) {
    if (!wet[s.point]) continue;
    const Eigen::Quaterniond& q = motion[s.body].orientation;
    const Vec3 offset = q * s.offset;
    double p = pressure[s.point] + density * (gravity - acceleration[s.point]).dot(offset);
    if (!keep_negative) p = std::max(p, 0.0);
    force[s.point] -= p * s.area * (q * s.normal);
  }
}

}  // namespace sluice
