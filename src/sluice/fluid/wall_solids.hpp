// Whether a point lies in a wall's solid, as RigidBodies::nearest_on_walls sees the walls: behind
// a closed side of a tank, inside a box wall, or behind a plane. A few comparisons per wall, to
// pass over the fluid particles that are in no wall before asking where the nearest surface is.
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "sluice/io/case_config.hpp"

namespace sluice {

class WallSolids {
 public:
  WallSolids(const std::vector<io::WallConfig>& walls, int dimension) : dimension_(dimension) {
    for (const io::WallConfig& wall : walls) {
      switch (wall.shape) {
        case io::WallShape::kTank: {
          Tank tank{wall.box, {}};
          for (int axis = 0; axis < 3; ++axis) {
            for (int upper = 0; upper < 2; ++upper) {
              tank.closed[axis][upper] =
                  (dimension != 2 || axis != 1) && !wall.side_open(axis, upper);
            }
          }
          tanks_.push_back(tank);
          break;
        }
        case io::WallShape::kBox:
          boxes_.push_back(wall.box);
          break;
        case io::WallShape::kPlane:
          planes_.push_back({wall.point, wall.normal});
          break;
      }
    }
  }

  bool contains(const Vec3& x) const {
    for (const Tank& t : tanks_) {
      for (int axis = 0; axis < 3; ++axis) {
        if ((t.closed[axis][0] && x[axis] < t.box.min[axis]) ||
            (t.closed[axis][1] && x[axis] > t.box.max[axis]))
          return true;
      }
    }
    for (const AxisBox& b : boxes_) {
      bool inside = true;
      for (int axis = 0; axis < 3; ++axis) {
        if (dimension_ == 2 && axis == 1) continue;
        inside = inside && x[axis] > b.min[axis] && x[axis] < b.max[axis];
      }
      if (inside) return true;
    }
    for (const Plane& p : planes_) {
      if ((x - p.point).dot(p.normal) < 0) return true;
    }
    return false;
  }

 private:
  struct Tank {
    AxisBox box;
    std::array<std::array<bool, 2>, 3> closed;
  };
  struct Plane {
    Vec3 point, normal;  // the normal points into the fluid
  };
  int dimension_;
  std::vector<Tank> tanks_;
  std::vector<AxisBox> boxes_;
  std::vector<Plane> planes_;
};

}  // namespace sluice
