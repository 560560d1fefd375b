#include "sluice/fluid/mac/free_surface.hpp"

#include "sluice/fluid/mac/advection.hpp"
#include "sluice/fluid/mac/level_set.hpp"

namespace sluice {

namespace {
// Enright et al. reseed the marker particles every 20 steps.
constexpr long kReseedEvery = 20;
}  // namespace

template <int D>
FreeSurface<D>::FreeSurface(const MacGrid<D>& grid, CellField phi, int particles_per_cell,
                            int reinitialise_every)
    : grid_(grid), phi_(std::move(phi)), reinitialise_every_(reinitialise_every) {
  if (particles_per_cell > 0) {
    markers_.emplace(particles_per_cell);
    markers_->reseed(grid_, phi_);
  }
}

template <int D>
void FreeSurface<D>::advance(const FaceField<D>& u, Real dt) {
  ++steps_;
  phi_ = advect_maccormack(grid_.cell_lattice(), phi_, grid_, u, dt);
  if (markers_) {
    markers_->advect(grid_, u, dt);
    markers_->correct(grid_, phi_);
  }
  if (steps_ % reinitialise_every_ == 0) reinitialise<D>(grid_, phi_);
  if (markers_) {
    markers_->correct(grid_, phi_);
    markers_->adjust_radii(grid_, phi_);
    if (steps_ % kReseedEvery == 0) markers_->reseed(grid_, phi_);
  }
}

template <int D>
void FreeSurface<D>::carry_through(const std::vector<char>& solid) {
  const Lattice<D> cells = grid_.cell_lattice();
  std::vector<char> known(solid.size());
  std::vector<std::size_t> pending;
  for (std::size_t k = 0; k < solid.size(); ++k) {
    known[k] = !solid[k];
    if (solid[k]) pending.push_back(k);
  }
  std::vector<std::pair<std::size_t, Real>> layer;
  while (!pending.empty()) {
    layer.clear();
    std::vector<std::size_t> rest;
    for (const std::size_t k : pending) {
      const GridIndex<D> c = cells.coordinates(k);
      Real sum = 0;
      int count = 0;
      for (int a = 0; a < D; ++a) {
        for (const int side : {-1, 1}) {
          GridIndex<D> n = c;
          n[a] += side;
          if (!cells.contains(n) || !known[cells.index(n)]) continue;
          sum += phi_[cells.index(n)];
          ++count;
        }
      }
      if (count > 0) {
        layer.emplace_back(k, sum / count);
      } else {
        rest.push_back(k);
      }
    }
    if (layer.empty()) break;  // solid cells with no way out: left as they are
    for (const auto& [k, value] : layer) {
      phi_[k] = value;
      known[k] = 1;
    }
    pending = std::move(rest);
  }
}

template class FreeSurface<2>;
template class FreeSurface<3>;

}  // namespace sluice
