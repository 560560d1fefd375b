// The case's walls as a sphere meets them, one surface each: every closed side of a tank a
// half-space (its plane, the normal into the tank), a box wall a solid box, a plane wall its
// half-space. In 2D (the x-z plane) a tank has no y sides and a box reaches across y.
#pragma once

#include <limits>
#include <vector>

#include "sluice/geometry/signed_distance.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/io/wall_pieces.hpp"

namespace sluice {

class SphereWalls {
 public:
  SphereWalls(const std::vector<io::WallConfig>& walls, int dimension) {
    for_each_wall_piece(
        walls, dimension,
        [&](const io::WallConfig&, const Vec3& point, const Vec3& normal) {
          surfaces_.push_back({true, point, normal, Vec3::Zero()});
        },
        [&](const io::WallConfig&, const Vec3& centre, const Vec3& half) {
          surfaces_.push_back({false, centre, Vec3::Zero(), half});
        });
  }

  std::size_t size() const { return surfaces_.size(); }

  // Surface w nearest to x: the signed distance (< 0 in the wall's solid) and the normal out
  // of the solid.
  SurfacePoint nearest(std::size_t w, const Vec3& x) const {
    const Surface& s = surfaces_[w];
    if (s.plane) return plane_surface(s.point, s.normal, x);
    SurfacePoint p = box_surface(s.half, x - s.point);
    p.closest += s.point;
    return p;
  }

 private:
  struct Surface {
    bool plane = true;
    Vec3 point, normal;  // a plane's point and normal; a box's centre
    Vec3 half;           // a box's half extents
  };
  std::vector<Surface> surfaces_;
};

}  // namespace sluice
