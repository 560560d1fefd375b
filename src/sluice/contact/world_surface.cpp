#include "sluice/contact/world_surface.hpp"

namespace sluice {

void WorldSurface::update(const ContactShape& shape, const SystemBody& body, double cell) {
  const bool never_moves = body.fixed && !body.prescribed;
  if (never_moves && placed_once_) return;
  const std::size_t n = shape.surface_position.size();
  points_.resize(n);
  normals_.resize(n);
  bounds_ = AxisBox::empty();
  for (std::size_t k = 0; k < n; ++k) {
    points_[k] = body.state.position + body.state.orientation * shape.surface_position[k];
    normals_[k] = body.state.orientation * shape.surface_normal[k];
    bounds_.grow(points_[k]);
  }
  placed_once_ = true;
  grid_ = PointGrid{};
  if (never_moves) grid_.build(points_, nullptr, cell);
}

void WorldSurface::near(const AxisBox& region, double margin,
                        std::vector<std::uint32_t>& out) const {
  out.clear();
  if (!region.overlaps(bounds_, margin)) return;
  const Vec3 lo = (region.min.array() - margin).max(bounds_.min.array());
  const Vec3 hi = (region.max.array() + margin).min(bounds_.max.array());
  auto keep = [&](std::uint32_t k) {
    if (region.contains_within(points_[k], margin)) out.push_back(k);
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
