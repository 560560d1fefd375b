// A contact body's surface particles in world coordinates, with their bounding box. A body that
// never moves (a wall, a fixed body) is placed once and its particles indexed by a grid, so that
// finding the particles near a region reads only those: the cost of contact follows the
// particles near contact, not the size of the walls.
#pragma once

#include <cstdint>
#include <vector>

#include "sluice/contact/contact_body.hpp"
#include "sluice/contact/point_grid.hpp"
#include "sluice/geometry/axis_box.hpp"

namespace sluice {

class WorldSurface {
 public:
  // Places the particles of `shape` where `body` is (again, unless it never moves and was
  // placed before); `cell` is the grid's cell size for bodies that never move.
  void update(const ContactShape& shape, const SystemBody& body, double cell);

  const std::vector<Vec3>& points() const { return points_; }
  const std::vector<Vec3>& normals() const { return normals_; }
  const AxisBox& bounds() const { return bounds_; }

  // Indices of the particles inside `region` grown by `margin`.
  void near(const AxisBox& region, double margin, std::vector<std::uint32_t>& out) const;
  // The grid of all particles of a body that never moves; empty for the others.
  const PointGrid& grid() const { return grid_; }

 private:
  std::vector<Vec3> points_, normals_;
  AxisBox bounds_;
  bool placed_once_ = false;
  PointGrid grid_;
};

}  // namespace sluice
