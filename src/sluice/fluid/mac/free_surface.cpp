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

template class FreeSurface<2>;
template class FreeSurface<3>;

}  // namespace sluice
