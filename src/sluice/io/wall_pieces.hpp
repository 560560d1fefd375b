// A case's walls as simple pieces, in the walls' order: each closed side of a tank a plane whose
// solid lies outside the tank, each plane wall its plane, each box wall a solid box. In 2D (the
// x-z plane) a tank has no y sides and a box reaches across y (an infinite half size).
#pragma once

#include <limits>
#include <vector>

#include "sluice/io/case_config.hpp"

namespace sluice {

// Calls on_plane(wall, point, normal into the fluid) and on_box(wall, centre, half sizes).
template <class OnPlane, class OnBox>
void for_each_wall_piece(const std::vector<io::WallConfig>& walls, int dimension,
                         OnPlane&& on_plane, OnBox&& on_box) {
  for (const io::WallConfig& wall : walls) {
    switch (wall.shape) {
      case io::WallShape::kTank:
        for (int axis = 0; axis < 3; ++axis) {
          if (dimension == 2 && axis == 1) continue;
          for (const bool upper : {false, true}) {
            if (wall.side_open(axis, upper)) continue;
            Vec3 normal = Vec3::Zero();
            normal[axis] = upper ? -1 : 1;
            on_plane(wall, upper ? wall.box.max : wall.box.min, normal);
          }
        }
        break;
      case io::WallShape::kBox: {
        Vec3 half = 0.5 * (wall.box.max - wall.box.min);
        if (dimension == 2) half[1] = std::numeric_limits<double>::infinity();
        on_box(wall, Vec3(0.5 * (wall.box.min + wall.box.max)), half);
        break;
      }
      case io::WallShape::kPlane:
        on_plane(wall, wall.point, wall.normal);
        break;
    }
  }
}

}  // namespace sluice
