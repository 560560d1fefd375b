// Velocities carried from the water into the air next to it, so that advection and the
// interface see a smooth field: each face that the projection did not set takes the value
// that solves grad(u) . grad(phi) = 0 upwind from the water, by fast sweeping (Zhao 2005;
// the extension velocities of Adalsteinsson & Sethian, JCP 148, 1999).
#pragma once

#include <limits>
#include <vector>

#include "sluice/fluid/mac/mac_grid.hpp"

namespace sluice {

// Marks per face of each axis: the faces whose velocity is known (non-zero).
template <int D>
using FaceMarks = std::array<std::vector<char>, D>;

// Fills every face of `u` not marked in `known`, up to `band` [m] from the surface, from its
// neighbours nearer the water (smaller phi, phi taken at a face as the mean of its cells').
// Faces farther out, and those no known value reaches, keep theirs: advection never samples
// farther than a few cells into the air.
template <int D>
void extend_velocity(const MacGrid<D>& grid, const CellField& phi, const FaceMarks<D>& known,
                     FaceField<D>& u, Real band = std::numeric_limits<Real>::infinity());

// phi at the faces of `axis`: the mean of the two cells beside each (the one cell on the
// grid's boundary).
template <int D>
std::vector<Real> phi_at_faces(const MacGrid<D>& grid, const CellField& phi, int axis);

}  // namespace sluice
