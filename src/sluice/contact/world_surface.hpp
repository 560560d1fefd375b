// A contact body's surface particles in world coordinates, with their bounding box. A body that
// never moves (a wall, a fixed body) is placed once and its particles indexed by a grid, so that
// finding the particles near a region reads only those: the cost of contact follows the
// particles near contact, not the size of the walls.
#pragma once

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

class WorldSurface {
 public:
  // Places the particles of `body` (again, unless it never moves and was placed before);
  // `cell` is the grid's cell size for bodies that never move.
  void update(const ContactBody& body, double cell);

  const std::vector<Vec3>& points() const { return points_; }
  const std::vector<Vec3>& normals() const { return normals_; }
  const Bounds& bounds() const { return bounds_; }

  // Indices, in increasing order within each grid cell, of the particles inside `region` grown
  // by `margin`.
  void near(const Bounds& region, double margin, std::vector<std::uint32_t>& out) const;

 private:
  std::int64_t key(const Vec3& p) const;

  std::vector<Vec3> points_, normals_;
  Bounds bounds_;
  bool placed_once_ = false;
  double cell_ = 0;
  std::unordered_map<std::int64_t, std::vector<std::uint32_t>> grid_;  // bodies that never move
};

}  // namespace sluice
