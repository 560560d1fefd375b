// The free surface as the model carries it: the level set, advected by MacCormack's scheme,
// corrected by its marker particles (the particle level set) and reinitialised.
#pragma once

#include <optional>

#include "sluice/fluid/mac/mac_grid.hpp"
#include "sluice/fluid/mac/particle_level_set.hpp"
#include "sluice/fluid/mac/pressure_projection.hpp"

namespace sluice {

template <int D>
class FreeSurface {
 public:
  // `phi` at the start; `particles_per_cell` marker particles per cell and sign (0: none);
  // reinitialisation every `reinitialise_every` steps.
  FreeSurface(const MacGrid<D>& grid, CellField phi, int particles_per_cell,
              int reinitialise_every);

  // One step of `dt` in the flow `u`: the level set and the markers carried, then corrected
  // and reinitialised. `solid` says which faces of the grid's boundary open to air.
  void advance(const FaceField<D>& u, Real dt, const SolidFaces<D>& solid);

  // Shifts the level set by one value so that the water it holds outside the `excluded` cells
  // is `volume` (volume_correction.hpp), the markers moved with the surface (once the shifts
  // add up to a hundredth of a cell). Returns the volume this added.
  double keep_volume(const std::vector<char>& excluded, double volume);

  // Carries the level set through the cells marked `solid` from the cells around them, layer by
  // layer (each the mean of its neighbours already set), so that the surface runs on through a
  // body as if it were water: where the body moves away, the water it uncovers is the water its
  // surroundings say, and the volume is kept.
  void carry_through(const std::vector<char>& solid);

  const CellField& phi() const { return phi_; }
  // The level set edited where the case sets it (an inlet's water) by edit(phi); the markers
  // are kept.
  template <class Edit>
  void edit_phi(Edit&& edit) {
    edit(phi_);
  }
  std::size_t marker_count() const { return markers_ ? markers_->size() : 0; }

  // Checkpoints: the level set, the markers, and the step count that paces reinitialisation.
  void archive_state(StateArchive& a) {
    a(phi_, steps_);
    if (markers_) markers_->archive_state(a);
  }
  // Checkpoints of a run that keeps the volume: the shift the markers have yet to follow.
  void archive_kept_volume(StateArchive& a) { a(unfollowed_shift_); }

 private:
  // Where the flow comes in across a face of the grid's boundary that opens to air, the air
  // it brings, which the advection's sampling (held at the last cell) cannot see.
  void let_air_in(const FaceField<D>& u, Real dt, const SolidFaces<D>& solid,
                  const CellField& before);

  MacGrid<D> grid_;
  CellField phi_;
  std::optional<ParticleLevelSet<D>> markers_;
  int reinitialise_every_;
  long steps_ = 0;
  Real unfollowed_shift_ = 0;  // keep_volume's shifts since the markers last followed
};

}  // namespace sluice
