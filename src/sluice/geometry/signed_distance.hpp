// The nearest point of a shape's surface to a point, with the signed distance (negative inside
// the solid) and the outward normal there: what a boundary model (penalty forces, a level set)
// asks of bodies and walls. Shapes in their own frame, centred at the origin.
#pragma once

#include <vector>

#include "sluice/core/types.hpp"

namespace sluice {

struct SurfacePoint {
  double distance = 0;           // signed: < 0 inside the solid
  Vec3 closest = Vec3::Zero();   // on the surface
  Vec3 normal = Vec3::Zero();    // outward unit normal of the surface at `closest`
  Vec3 velocity = Vec3::Zero();  // of a wall's moving surface (WallConfig::surface_velocity)
};

// A box of half extents `half` (an infinite one along an axis given +infinity).
SurfacePoint box_surface(const Vec3& half, const Vec3& x);
// A sphere of radius r.
SurfacePoint sphere_surface(double r, const Vec3& x);
// A cylinder of radius r along z, from -half_length to half_length, with flat caps.
SurfacePoint cylinder_surface(double r, double half_length, const Vec3& x);
// The plane through `point` with unit `normal` pointing out of the solid.
SurfacePoint plane_surface(const Vec3& point, const Vec3& normal, const Vec3& x);
// A surface known by samples (a mesh's surface particles, each with its face's outward
// normal): the plane of the nearest sample's face. Exact on flat faces near their middle.
SurfacePoint sampled_surface(const std::vector<Vec3>& position, const std::vector<Vec3>& normal,
                             const Vec3& x);

}  // namespace sluice
