#include "sluice/contact/world_surface.hpp"

#include "sluice/contact/multibody_system.hpp"

#include <cmath>

namespace sluice {

namespace {
constexpr std::int64_t kAxisCells = std::int64_t(1) << 20;  // cells per axis in a key
}

std::int64_t WorldSurface::key(const Vec3& p) const {
  std::int64_t k = 0;
  for (int a = 0; a < 3; ++a) {
    const auto c = static_cast<std::int64_t>(std::floor(p[a] / cell_)) + kAxisCells / 2;
    k = k * kAxisCells + c;
  }
  return k;
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
  grid_.clear();
  if (!never_moves) return;
  cell_ = cell;
  for (std::size_t k = 0; k < n; ++k)
    grid_[key(points_[k])].push_back(static_cast<std::uint32_t>(k));
}

void WorldSurface::near(const Bounds& region, double margin,
                        std::vector<std::uint32_t>& out) const {
  out.clear();
  if (!region.overlaps(bounds_, margin)) return;
  // A grid query visits the cells of the region; when they outnumber the particles, a plain
  // scan is cheaper.
  double cells = 1;
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
  if (!grid_.empty()) {
    lo = (region.min.array() - margin).max(bounds_.min.array());
    hi = (region.max.array() + margin).min(bounds_.max.array());
    for (int a = 0; a < 3; ++a) cells *= std::floor(hi[a] / cell_) - std::floor(lo[a] / cell_) + 1;
  }
  if (grid_.empty() || cells > static_cast<double>(points_.size())) {
    for (std::size_t k = 0; k < points_.size(); ++k) {
      if (region.contains(points_[k], margin)) out.push_back(static_cast<std::uint32_t>(k));
    }
    return;
  }
  const auto first = [&](int a) { return static_cast<std::int64_t>(std::floor(lo[a] / cell_)); };
  const auto last = [&](int a) { return static_cast<std::int64_t>(std::floor(hi[a] / cell_)); };
  for (std::int64_t i = first(0); i <= last(0); ++i) {
    for (std::int64_t j = first(1); j <= last(1); ++j) {
      for (std::int64_t k = first(2); k <= last(2); ++k) {
        const std::int64_t cell_key =
            ((i + kAxisCells / 2) * kAxisCells + (j + kAxisCells / 2)) * kAxisCells +
            (k + kAxisCells / 2);
        const auto found = grid_.find(cell_key);
        if (found == grid_.end()) continue;
        for (std::uint32_t p : found->second) {
          if (region.contains(points_[p], margin)) out.push_back(p);
        }
      }
    }
  }
}

}  // namespace sluice
