// A square (2D) or cubic (3D) block of lattice points for the MPS unit tests, sorted into a
// cell list with its neighbour list.
#pragma once

#include <cstdint>
#include <vector>

#include "sluice/fluid/mps/neighbour_list.hpp"
#include "sluice/neighbor/cell_list.hpp"

namespace sluice {

template <int D>
struct MpsTestLattice {
  std::vector<Vec<D>> x;
  CellList<D> cells;
  NeighbourList<D> neighbours;
  std::size_t centre = 0;

  MpsTestLattice(int half_width, double l0, double re) {
    std::vector<Vec<D>> points;
    for (int i = -half_width; i <= half_width; ++i) {
      for (int j = -half_width; j <= half_width; ++j) {
        for (int k = (D == 3 ? -half_width : 0); k <= (D == 3 ? half_width : 0); ++k) {
          Vec<D> p;
          if constexpr (D == 2) {
            p << i * l0, j * l0;
          } else {
            p << i * l0, j * l0, k * l0;
          }
          points.push_back(p + Vec<D>::Constant(0.3 * l0));  // off the origin: any place
        }
      }
    }
    cells = CellList<D>(points.front(), points.back(), re);
    std::vector<std::uint32_t> order;
    cells.sort(points, order);
    for (std::uint32_t o : order) x.push_back(points[o]);
    for (std::size_t i = 0; i < x.size(); ++i) {
      if ((x[i] - Vec<D>::Constant(0.3 * l0)).norm() < 1e-9) centre = i;
    }
    neighbours.build(x, cells, re, [](std::size_t) { return true; });
  }
};

}  // namespace sluice
