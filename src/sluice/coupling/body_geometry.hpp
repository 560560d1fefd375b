// What a fluid may ask of the bodies' shapes when it builds its boundary: points fixed in each
// body, layer by layer under its surface, and whether a place is taken by a body. The case's
// bodies implement it (sim/rigid_bodies.hpp).
#pragma once

#include <vector>

#include "sluice/coupling/body_motion.hpp"

namespace sluice {

class BodyGeometry {
 public:
  virtual ~BodyGeometry() = default;
  virtual std::size_t body_count() const = 0;
  // The bodies' kinematics now (no acceleration yet).
  virtual std::vector<BodyKinematics> motion() const = 0;
  // Points at depths dx/2, 3 dx/2, ... under each body's surface, `layers` of them: a fluid
  // whose boundary lies half a spacing outside its boundary particles then meets the true
  // surface.
  virtual std::vector<BodyPoint> points_under_surface(int layers) const = 0;
  // The surface particles that contact uses, on each body's faces.
  virtual std::vector<BodyPoint> surface_points() const = 0;
  // Whether x lies inside a body or closer than `clearance` to its surface particles.
  virtual bool occupies(const Vec3& x, double clearance) const = 0;
};

}  // namespace sluice
