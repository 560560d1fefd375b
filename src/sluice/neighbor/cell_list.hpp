// Cell-linked-list neighbour search with cells as wide as the search radius. Particles are
// sorted by cell (x fastest), so the three cells of a row along x are one contiguous index
// range: a 3D query scans 9 ranges, a 2D query 3, and neighbours sit close in memory. (Cells
// of half the radius scan 42 % less volume but cut the ranges into pieces too short for SIMD
// loops: measured slower, docs/performance.md.)
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "sluice/core/state_archive.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

template <int D>
class CellList {
 public:
  CellList() = default;
  // Cells of edge `radius` cover [lo, hi]; positions outside are clamped to the border
  // cells, so a stray particle is still found (the divergence guard reports it).
  CellList(const Vec<D>& lo, const Vec<D>& hi, Real radius);

  // Sorts particles by cell: fills `order` (new index k holds old particle order[k]).
  // Call reorder on the particle set with it, then `positions` are sorted.
  void sort(const std::vector<Vec<D>>& positions, std::vector<std::uint32_t>& order);

  Real radius() const { return kReach * cell_size_; }

  // Checkpoints: the cells of the last sort (the particles have moved since).
  void archive_state(StateArchive& a) { a(cell_start_); }

  // Calls fn(j, r_ij, r2) for every particle j != i with |r_i - r_j|^2 < radius2
  // (r_ij = r_i - r_j). radius2 must not exceed radius()^2.
  template <class Fn>
  void for_each_neighbor(const std::vector<Vec<D>>& positions, std::size_t i, Real radius2,
                         Fn&& fn) const {
    const Vec<D>& xi = positions[i];
    for_each_near(positions, xi, radius2, [&](std::size_t j, const Vec<D>& rij, Real r2) {
      if (j != i) fn(j, rij, r2);
    });
  }

  // Calls fn(j, x - r_j, r2) for every particle j with |x - r_j|^2 < radius2.
  template <class Fn>
  void for_each_near(const std::vector<Vec<D>>& positions, const Vec<D>& x, Real radius2,
                     Fn&& fn) const {
    for_each_candidate_range(x, [&](std::uint32_t begin, std::uint32_t end) {
      scan(positions, x, radius2, begin, end, fn);
    });
  }

  // Calls fn(begin, end) for the contiguous index ranges that hold every particle within
  // radius() of x (and some farther ones): for loops that test distances themselves, e.g.
  // branch-free SIMD loops over kernels that vanish beyond their support.
  template <class Fn>
  void for_each_candidate_range(const Vec<D>& x, Fn&& fn) const {
    const auto c = cell_coords(x);
    if constexpr (D == 2) {
      for (int dz = -kReach; dz <= kReach; ++dz) {
        const std::size_t row = linear(c[0], c[1] + dz);
        fn(cell_start_[row - kReach], cell_start_[row + kReach + 1]);
      }
    } else {
      for (int dz = -kReach; dz <= kReach; ++dz) {
        for (int dy = -kReach; dy <= kReach; ++dy) {
          const std::size_t row = linear(c[0], c[1] + dy, c[2] + dz);
          fn(cell_start_[row - kReach], cell_start_[row + kReach + 1]);
        }
      }
    }
  }

  // The cell of a position, clamped to the interior so that all scanned cells exist.
  std::array<int, D> cell_coords(const Vec<D>& x) const {
    std::array<int, D> c{};
    for (int a = 0; a < D; ++a) {
      const Real offset = (x[a] - lo_[a]) * inverse_cell_size_;
      const int k =
          (offset < 0 ? 0 : static_cast<int>(std::min<Real>(offset, counts_[a]))) + kReach;
      c[a] = std::min(k, counts_[a] - 1 - kReach);
    }
    return c;
  }

 private:
  template <class Fn>
  static void scan(const std::vector<Vec<D>>& positions, const Vec<D>& x, Real radius2,
                   std::uint32_t begin, std::uint32_t end, Fn& fn) {
    for (std::uint32_t j = begin; j < end; ++j) {
      const Vec<D> rij = x - positions[j];
      const Real r2 = rij.squaredNorm();
      if (r2 < radius2) fn(j, rij, r2);
    }
  }

  std::size_t linear(int x, int z) const { return static_cast<std::size_t>(x + counts_[0] * z); }
  std::size_t linear(int x, int y, int z) const {
    return static_cast<std::size_t>(x + counts_[0] * (y + counts_[1] * z));
  }
  std::size_t linear(const std::array<int, D>& c) const {
    if constexpr (D == 2) {
      return linear(c[0], c[1]);
    } else {
      return linear(c[0], c[1], c[2]);
    }
  }

  Vec<D> lo_ = Vec<D>::Zero();
  Real cell_size_ = 0;
  Real inverse_cell_size_ = 0;
  static constexpr int kReach = 1;  // cells scanned on each side of a particle's cell
  std::array<int, D> counts_{};     // including kReach padding cells on each side
  std::vector<std::uint32_t>
      cell_start_;                      // particles of cell c: [cell_start_[c], cell_start_[c+1])
  std::vector<std::uint32_t> cell_of_;  // scratch: cell of each particle before sorting
};

}  // namespace sluice
