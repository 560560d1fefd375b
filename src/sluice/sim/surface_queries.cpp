// RigidBodies' distance queries: each body's analytic shape (a mesh: its surface particles'
// faces) and the walls, for boundary models.
#include <algorithm>
#include <limits>

#include "sluice/io/wall_pieces.hpp"
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
  auto keep = [&](const io::WallConfig& wall, const SurfacePoint& p) {
    if (p.distance < best.distance) {
      best = p;
      best.velocity = wall.surface_velocity;
    }
  };
  for_each_wall_piece(
      walls_, dimension_,
      [&](const io::WallConfig& wall, const Vec3& point, const Vec3& normal) {
        keep(wall, plane_surface(point, normal, x));
      },
      [&](const io::WallConfig& wall, const Vec3& centre, const Vec3& half) {
        SurfacePoint p = box_surface(half, x - centre);
        p.closest += centre;
        keep(wall, p);
      });
  return best;
}

}  // namespace sluice
