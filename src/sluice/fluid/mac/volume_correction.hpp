// Keeping the level set's water: advection and reinitialisation lose what the grid cannot
// resolve (a splash's sheets and drops thinner than a cell), and the loss does not shrink on
// finer cells (docs/validation.md, F3). After each step the level set is shifted by one value
// everywhere, the surface moved along its normal by the same small distance, so that the water
// it holds is what it held before, less what left across the grid's boundary. The water lost
// in a splash is put back along the whole surface: the volume is kept, not where it was.
#pragma once

#include <vector>

#include "sluice/fluid/mac/mac_grid.hpp"
#include "sluice/fluid/mac/pressure_projection.hpp"

namespace sluice {

// Whether face `f` of axis `a` on the grid's boundary opens to air: open, and no outlet.
template <int D>
bool opens_to_air(const SolidFaces<D>& solid, int a, std::size_t f);

// The water's volume (2D: area) in `phi`, each cell by its smeared fraction, the cells marked
// in `excluded` (the solids) left out.
template <int D>
double water_volume_of(const MacGrid<D>& grid, const CellField& phi,
                       const std::vector<char>& excluded);

// The volume of water the face velocities `u` carry into the grid across its boundary over
// `dt` (negative: out), a closed face's velocity its solid's. Out of a cell, its water
// fraction; in across an inlet's or an outlet's face, the same (advection brings in what the
// cell beside it holds); in across a face open to air, none (FreeSurface lets air in there).
template <int D>
double boundary_inflow(const MacGrid<D>& grid, const FaceField<D>& u, const CellField& phi,
                       const SolidFaces<D>& solid, Real dt);

// What shift_to_volume did: the shift added to phi and the volume it added.
struct VolumeShift {
  Real shift = 0;
  double added = 0;
};

// Shifts `phi` by one value so that water_volume_of(grid, phi, excluded) is `volume`, by
// Newton's method on the piecewise linear volume, the shift at most a quarter of a cell (a
// surface almost gone is not blown up).
template <int D>
VolumeShift shift_to_volume(const MacGrid<D>& grid, CellField& phi,
                            const std::vector<char>& excluded, double volume);

}  // namespace sluice
