// The case's walls as a sphere meets them, one surface each: every closed side of a tank a
// half-space (its plane, the normal into the tank), a box wall a solid box, a plane wall its
// half-space. In 2D (the x-z plane) a tank has no y sides and a box reaches across y.
#pragma once

#include <limits>
#include <vector>

#include "sluice/geometry/signed_distance.hpp"
#include "sluice/io/case_config.hpp"

namespace sluice {

class SphereWalls {
 public:
  SphereWalls(const std::vector<io::WallConfig>& walls, int dimension) {
    for (const io::WallConfig& w : walls) {
      switch (w.shape) {
        case io::WallShape::kTank:
          for (int axis = 0; axis < 3; ++axis) {
            if (dimension == 2 && axis == 1) continue;
            for (const bool upper : {false, true}) {
              if (w.side_open(axis, upper)) continue;
              Vec3 normal = Vec3::Zero();
              normal[axis] = upper ? -1 : 1;
              surfaces_.push_back({true, upper ? w.box.max : w.box.min, normal, Vec3::Zero()});
            }
          }
          break;
        case io::WallShape::kBox: {
          Vec3 half = 0.5 * (w.box.max - w.box.min);
          if (dimension == 2) half[1] = std::numeric_limits<double>::infinity();
          surfaces_.push_back({false, 0.5 * (w.box.min + w.box.max), Vec3::Zero(), half});
          break;
        }
        case io::WallShape::kPlane:
          surfaces_.push_back({true, w.point, w.normal, Vec3::Zero()});
          break;
      }
    }
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
