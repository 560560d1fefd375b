// The free surface as the zero level of a signed distance phi at the cell centres (negative in
// the water): built from the case's fluid blocks, and kept a distance by reinitialisation
// with the fast sweeping method (Zhao, Math. Comp. 74, 2005).
#pragma once

#include <vector>

#include "sluice/fluid/mac/mac_grid.hpp"
#include "sluice/geometry/axis_box.hpp"

namespace sluice {

// Signed distance to the union of `blocks` (3D boxes; 2D: their x-z section) at the cell
// centres. A block's side that lies on the domain's boundary is no surface (the water goes on
// into the wall), so it is taken as reaching beyond the domain.
template <int D>
CellField level_set_of_blocks(const MacGrid<D>& grid, const std::vector<AxisBox>& blocks,
                              const AxisBox& domain);

// Replaces phi by the signed distance to its zero level. The cells next to a sign change keep
// the distance that linear interpolation along the axes gives; the rest are swept in the 2^D
// diagonal orders, `rounds` times.
template <int D>
void reinitialise(const MacGrid<D>& grid, CellField& phi, int rounds = 2);

// Calls visit(k) for each cell index in each of the 2^D diagonal orders (a sweep).
template <int D, class Visit>
void for_each_sweep(const Lattice<D>& lattice, Visit&& visit) {
  for (int order = 0; order < (1 << D); ++order) {
    GridIndex<D> c{};
    // An odometer whose digits run forward or backward by the order's bits.
    auto start = [&](int a) { return ((order >> a) & 1) ? lattice.dims[a] - 1 : 0; };
    for (int a = 0; a < D; ++a) c[a] = start(a);
    while (true) {
      visit(lattice.index(c), c);
      int a = 0;
      for (; a < D; ++a) {
        const int step = ((order >> a) & 1) ? -1 : 1;
        c[a] += step;
        if (c[a] >= 0 && c[a] < lattice.dims[a]) break;
        c[a] = start(a);
      }
      if (a == D) break;
    }
  }
}

}  // namespace sluice
