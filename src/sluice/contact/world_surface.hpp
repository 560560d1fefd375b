// A contact body's surface particles in world coordinates, with their bounding box. A body that
// never moves (a wall, a fixed body) is placed once and its particles indexed by a grid, so that
// finding the particles near a region reads only those: the cost of contact follows the
// particles near contact, not the size of the walls.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

#include "sluice/core/types.hpp"

namespace sluice {

struct ContactBody;

struct Bounds {
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 max = -Vec3::Constant(std::numeric_limits<double>::infinity());
  void grow(const Vec3& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  bool contains(const Vec3& p, double margin) const {
    return (p.array() >= min.array() - margin).all() && (p.array() <= max.array() + margin).all();
  }
  bool overlaps(const Bounds& o, double margin) const {
    return (min.array() - margin <= o.max.array()).all() &&
           (o.min.array() - margin <= max.array()).all();
  }
};

// Points hashed into cubic cells: visiting the points in a box, or within one cell of a point,
// reads only the cells there.
class PointGrid {
 public:
  // Indexes `points` (all of them, or those listed in `subset`) in cells of size `cell`.
  void build(const std::vector<Vec3>& points, const std::vector<std::uint32_t>* subset,
             double cell);
  bool empty() const { return cells_.empty(); }
  // Cells overlapping [lo, hi]; fn(index) for each point in them (not tested against the box).
  template <class Fn>
  void for_each_in_cells(const Vec3& lo, const Vec3& hi, Fn&& fn) const {
    const Cell first = cell_of(lo), last = cell_of(hi);
    for (std::int64_t i = first[0]; i <= last[0]; ++i) {
      for (std::int64_t j = first[1]; j <= last[1]; ++j) {
        for (std::int64_t k = first[2]; k <= last[2]; ++k) {
          const auto found = cells_.find(key({i, j, k}));
          if (found == cells_.end()) continue;
          for (std::uint32_t p : found->second) fn(p);
        }
      }
    }
  }
  // The cells in [lo, hi] (to choose between a grid query and a plain scan).
  double cells_in(const Vec3& lo, const Vec3& hi) const;

 private:
  using Cell = std::array<std::int64_t, 3>;
  Cell cell_of(const Vec3& p) const;
  static std::int64_t key(const Cell& c);

  double cell_ = 1;
  std::unordered_map<std::int64_t, std::vector<std::uint32_t>> cells_;
};

class WorldSurface {
 public:
  // Places the particles of `body` (again, unless it never moves and was placed before);
  // `cell` is the grid's cell size for bodies that never move.
  void update(const ContactBody& body, double cell);

  const std::vector<Vec3>& points() const { return points_; }
  const std::vector<Vec3>& normals() const { return normals_; }
  const Bounds& bounds() const { return bounds_; }

  // Indices of the particles inside `region` grown by `margin`.
  void near(const Bounds& region, double margin, std::vector<std::uint32_t>& out) const;
  // The grid of all particles of a body that never moves; empty for the others.
  const PointGrid& grid() const { return grid_; }

 private:
  std::vector<Vec3> points_, normals_;
  Bounds bounds_;
  bool placed_once_ = false;
  PointGrid grid_;
};

}  // namespace sluice
