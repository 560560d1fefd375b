#include "sluice/fluid/mac/free_surface.hpp"

#include <algorithm>
#include <cmath>

#include "sluice/fluid/mac/advection.hpp"
#include "sluice/fluid/mac/level_set.hpp"
#include "sluice/fluid/mac/volume_correction.hpp"

namespace sluice {

namespace {
// Enright et al. reseed the marker particles every 20 steps.
constexpr long kReseedEvery = 20;
constexpr Real kFollowShifts = 0.01;  // [cells]
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
void FreeSurface<D>::advance(const FaceField<D>& u, Real dt, const SolidFaces<D>& solid) {
  ++steps_;
  const CellField before = phi_;
  phi_ = advect_maccormack(grid_.cell_lattice(), phi_, grid_, u, dt);
  let_air_in(u, dt, solid, before);
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
double FreeSurface<D>::keep_volume(const std::vector<char>& excluded, double volume) {
  const VolumeShift shifted = shift_to_volume(grid_, phi_, excluded, volume);
  // The markers follow the shifts once these add up to a hundredth of a cell: every sphere is
  // a tenth of a cell or more, so none escapes for want of it, and following each step's
  // shift (typically a thousandth of a cell) made a 3D step a third slower.
  unfollowed_shift_ += shifted.shift;
  if (markers_ && std::abs(unfollowed_shift_) >= kFollowShifts * grid_.h) {
    markers_->follow_shift(grid_, phi_, unfollowed_shift_);
    unfollowed_shift_ = 0;
  }
  return shifted.added;
}

template <int D>
void FreeSurface<D>::let_air_in(const FaceField<D>& u, Real dt, const SolidFaces<D>& solid,
                                const CellField& before) {
  // Sampled beyond the last cell's centre, the level set holds that cell's value: a cell of
  // water on the boundary whose flow comes in from beyond would stay water for ever, a source
  // (a 2D dam break's jet, once it had reached the open top, fed a sheet of water down the
  // wall: with cells of 0.05 m, +37 % of its mass and seven times its energy by 4 s). Beyond
  // the face is air, the interface no farther out than the face. The ghost cell's level set is
  // max(phi + h, h / 2); the cell takes its upwind share of it, u dt / h, where that is more air.
  const Real h = grid_.h;
  for_each_boundary_face(grid_, [&](int a, int side, std::size_t k, std::size_t f) {
    if (!opens_to_air(solid, a, f)) return;
    const Real inward = side == 0 ? u[a][f] : -u[a][f];
    if (inward <= 0) return;
    const Real share = std::min(Real(1), inward * dt / h);
    const Real ghost = std::max(before[k] + h, Real(0.5) * h);
    phi_[k] = std::max(phi_[k], (1 - share) * before[k] + share * ghost);
  });
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
