#include "sluice/contact/point_grid.hpp"

#include <algorithm>
#include <cmath>

namespace sluice {

namespace {
constexpr std::int64_t kAxisCells = std::int64_t(1) << 20;  // cells per axis in a key
}

PointGrid::Cell PointGrid::cell_of(const Vec3& p) const {
  return {static_cast<std::int64_t>(std::floor(p[0] / cell_)),
          static_cast<std::int64_t>(std::floor(p[1] / cell_)),
          static_cast<std::int64_t>(std::floor(p[2] / cell_))};
}

std::int64_t PointGrid::key(const Cell& c) {
  return ((c[0] + kAxisCells / 2) * kAxisCells + (c[1] + kAxisCells / 2)) * kAxisCells +
         (c[2] + kAxisCells / 2);
}

void PointGrid::build(const std::vector<Vec3>& points, const std::vector<std::uint32_t>* subset,
                      double cell) {
  cell_ = cell;
  cells_.clear();
  if (subset) {
    for (std::uint32_t k : *subset) cells_[key(cell_of(points[k]))].push_back(k);
  } else {
    for (std::size_t k = 0; k < points.size(); ++k) {
      cells_[key(cell_of(points[k]))].push_back(static_cast<std::uint32_t>(k));
    }
  }
}

double PointGrid::cells_in(const Vec3& lo, const Vec3& hi) const {
  const Cell first = cell_of(lo), last = cell_of(hi);
  double count = 1;
  for (int a = 0; a < 3; ++a)
    count *= static_cast<double>(std::max<std::int64_t>(last[a] - first[a] + 1, 0));
  return count;
}

}  // namespace sluice
