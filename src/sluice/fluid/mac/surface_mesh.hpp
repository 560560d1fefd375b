// The free surface as a mesh for ParaView: the zero level of phi between the cell centres, as
// line segments in 2D (marching squares) and triangles in 3D (marching tetrahedra: each cube
// of eight centres cut into six tetrahedra about its diagonal, which needs no case table and
// has no ambiguous faces).
#pragma once

#include <vector>

#include "sluice/fluid/mac/mac_grid.hpp"

namespace sluice {

// The segments (2D) or triangles (3D) of phi's zero level, each as its own consecutive points
// (3D coordinates, x-z plane in 2D), in the order of io::PolyFrame with points_per_cell = D.
template <int D>
std::vector<Vec3> surface_mesh(const MacGrid<D>& grid, const CellField& phi);

}  // namespace sluice
