#include "sluice/contact/world_surface.hpp"

#include <cmath>

#include "sluice/contact/multibody_system.hpp"

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

void WorldSurface::update(const ContactBody& body, double cell) {
  const bool never_moves = body.fixed && !body.prescribed;
  if (never_moves && placed_once_) return;
  const std::size_t n = body.surface_position.size();
  points_.resize(n);
  normals_.resize(n);
  bounds_ = Bounds{};
  for (std::size_t k = 0; k < n; ++k) {
    points_[k] = body.state.position + body.state.orientation * body.surface_position[k];
    normals_[k] = body.state.orientation * body.surface_normal[k];
    bounds_.grow(points_[k]);
  }
  placed_once_ = true;
  grid_ = PointGrid{};
  if (never_moves) grid_.build(points_, nullptr, cell);
}

void WorldSurface::near(const Bounds& region, double margin,
                        std::vector<std::uint32_t>& out) const {
  out.clear();
  if (!region.overlaps(bounds_, margin)) return;
  const Vec3 lo = (region.min.array() - margin).max(bounds_.min.array());
  const Vec3 hi = (region.max.array() + margin).min(bounds_.max.array());
  auto keep = [&](std::uint32_t k) {
    if (region.contains(points_[k], margin)) out.push_back(k);
  };
  // A grid query visits the cells of the region; when they outnumber the particles, a plain
  // scan is cheaper.
  if (!grid_.empty() && grid_.cells_in(lo, hi) <= static_cast<double>(points_.size())) {
    grid_.for_each_in_cells(lo, hi, keep);
  } else {
    for (std::size_t k = 0; k < points_.size(); ++k) keep(static_cast<std::uint32_t>(k));
  }
}

}  // namespace sluice
