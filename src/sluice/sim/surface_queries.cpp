// RigidBodies' distance queries: each body's analytic shape (a mesh: its surface particles'
// faces) and the walls, for boundary models.
#include <algorithm>
#include <limits>

#include "sluice/sim/rigid_bodies.hpp"

namespace sluice {

SurfacePoint RigidBodies::nearest_on_body(std::size_t b, const Vec3& x) const {
  const RigidBody& s = state(b);
  const io::BodyConfig& c = configs_[b];
  const Vec3 principal = s.orientation.conjugate() * (x - s.position);
  if (c.shape == io::BodyShape::kMesh) {
    const ContactShape& shape = system_.shape(b);
    SurfacePoint p = sampled_surface(shape.surface_position, shape.surface_normal, principal);
    p.closest = s.position + s.orientation * p.closest;
    p.normal = s.orientation * p.normal;
    return p;
  }
  // In the shape's own frame, centred on the shape (box, sphere and cylinder are).
  const Vec3 local = axes_[b] * principal + centre_of_mass_[b];
  SurfacePoint p;
  const bool planar = dimension_ == 2;  // 2D: sections in the x-z plane
  switch (c.shape) {
    case io::BodyShape::kBox: {
      Vec3 half = 0.5 * c.size;
      if (planar) half[1] = std::numeric_limits<double>::infinity();
      p = box_surface(half, local);
      break;
    }
    case io::BodyShape::kSphere:
    case io::BodyShape::kCylinder:
      if (planar || c.shape == io::BodyShape::kSphere) {
        // A 2D disc is the sphere's section at y = 0.
        p = sphere_surface(c.radius, planar ? Vec3(local[0], 0, local[2]) : local);
        if (planar) p.closest[1] = local[1];
      } else {
        p = cylinder_surface(c.radius, 0.5 * c.length, local);
      }
      break;
    case io::BodyShape::kMesh:
      break;
  }
  const Eigen::Matrix3d to_world = s.orientation.toRotationMatrix() * axes_[b].transpose();
  p.closest = s.position + to_world * (p.closest - centre_of_mass_[b]);
  p.normal = to_world * p.normal;
  return p;
}

SurfacePoint RigidBodies::nearest_on_walls(const Vec3& x) const {
  SurfacePoint best;
  best.distance = std::numeric_limits<double>::infinity();
  best.closest = x;
  const io::WallConfig* current = nullptr;
  auto keep = [&](const SurfacePoint& p) {
    if (p.distance < best.distance) {
      best = p;
      best.velocity = current->surface_velocity;
    }
  };
  for (const io::WallConfig& wall : walls_) {
    current = &wall;
    switch (wall.shape) {
      case io::WallShape::kTank:
        // Each closed side is a plane whose solid lies outside the tank.
        for (int axis = 0; axis < 3; ++axis) {
          if (dimension_ == 2 && axis == 1) continue;
          for (const bool upper : {false, true}) {
            if (wall.side_open(axis, upper)) continue;
            Vec3 normal = Vec3::Zero();
            normal[axis] = upper ? -1 : 1;
            keep(plane_surface(upper ? wall.box.max : wall.box.min, normal, x));
          }
        }
        break;
      case io::WallShape::kBox: {
        const Vec3 centre = 0.5 * (wall.box.min + wall.box.max);
        Vec3 half = 0.5 * (wall.box.max - wall.box.min);
        if (dimension_ == 2) half[1] = std::numeric_limits<double>::infinity();
        SurfacePoint p = box_surface(half, x - centre);
        p.closest += centre;
        keep(p);
        break;
      }
      case io::WallShape::kPlane:
        keep(plane_surface(wall.point, wall.normal, x));
        break;
    }
  }
  return best;
}

}  // namespace sluice
