// Points hashed into cubic cells, for the narrow phase of contact.
#pragma once

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "sluice/core/types.hpp"

namespace sluice {

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

}  // namespace sluice
