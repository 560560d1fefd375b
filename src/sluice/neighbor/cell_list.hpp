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
#include "sluice/exec/host_device.hpp"

namespace sluice {

// The cell grid as plain data (no containers), so that a loop body on the host or on the device
// finds a particle's cell and its candidate ranges the same way. `cell_start` points to the
// first index of each cell, cells in the grid's order, with one more entry at the end.
template <int D>
struct CellGridView {
  static constexpr int kReach = 1;  // cells scanned on each side of a particle's cell
  Real lo[D] = {};
  Real inverse_cell_size = 0;
  int counts[D] = {};  // including kReach padding cells on each side
  const std::uint32_t* cell_start = nullptr;

  // The cell of a position, clamped to the interior so that all scanned cells exist.
  SLUICE_HOST_DEVICE void cell_coords(const Real* x, int* c) const {
    for (int a = 0; a < D; ++a) {
      const Real offset = (x[a] - lo[a]) * inverse_cell_size;
      const Real count = counts[a];
      const int k = (offset < 0 ? 0 : static_cast<int>(offset < count ? offset : count)) + kReach;
      c[a] = k < counts[a] - 1 - kReach ? k : counts[a] - 1 - kReach;
    }
  }
  SLUICE_HOST_DEVICE std::uint32_t linear(int x, int y, int z) const {
    return static_cast<std::uint32_t>(x + counts[0] * (y + counts[1] * z));
  }
  // The index of the cell holding x (2D: y is the model's second axis, here z).
  SLUICE_HOST_DEVICE std::uint32_t cell_of(const Real* x) const {
    int c[D];
    cell_coords(x, c);
    return D == 2 ? linear(c[0], c[D - 1], 0) : linear(c[0], c[1], c[D - 1]);
  }

  // Calls fn(begin, end) for the contiguous index ranges that hold every particle within one
  // cell of x (and some farther ones): the three cells of a row along x are one range.
  template <class Fn>
  SLUICE_HOST_DEVICE void for_each_candidate_range(const Real* x, Fn&& fn) const {
    int c[D];
    cell_coords(x, c);
    if constexpr (D == 2) {
      for (int dz = -kReach; dz <= kReach; ++dz) {
        const std::uint32_t row = linear(c[0], c[1] + dz, 0);
        fn(cell_start[row - kReach], cell_start[row + kReach + 1]);
      }
    } else {
      for (int dz = -kReach; dz <= kReach; ++dz) {
        for (int dy = -kReach; dy <= kReach; ++dy) {
          const std::uint32_t row = linear(c[0], c[1] + dy, c[2] + dz);
          fn(cell_start[row - kReach], cell_start[row + kReach + 1]);
        }
      }
    }
  }
};

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
  std::size_t cell_count() const { return cell_start_.size() - 1; }
  // The grid with the cells of the last sort.
  CellGridView<D> view() const {
    CellGridView<D> v = grid_;
    v.cell_start = cell_start_.data();
    return v;
  }

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
    view().for_each_candidate_range(x.data(), fn);
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

  static constexpr int kReach = CellGridView<D>::kReach;
  CellGridView<D> grid_;  // without its cell_start, which view() fills in
  Real cell_size_ = 0;
  std::vector<std::uint32_t>
      cell_start_;                      // particles of cell c: [cell_start_[c], cell_start_[c+1])
  std::vector<std::uint32_t> cell_of_;  // scratch: cell of each particle before sorting
};

}  // namespace sluice
