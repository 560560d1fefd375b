// Cell-linked-list neighbour search with cells as wide as the search radius. Particles are
// sorted by cell (x fastest), so a row of cells along x is one contiguous index range. A query
// scans the 9 rows around its cell (3 in 2D): the three cells of each, or for the costliest
// loops only those its search sphere reaches. (Cells of half the radius scan less volume
// but cut the ranges into pieces too short for SIMD loops; cells a quarter of the radius long
// along x scan less too, but sort every particle's neighbours by x, and with them F1's still
// tank grew currents past its bar in one build: docs/performance.md.)
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "sluice/core/host_device.hpp"
#include "sluice/core/state_archive.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

// The cell grid as plain data (no containers), so that a loop body on the host or on the device
// finds a particle's cell and its candidate ranges the same way. `cell_start` points to the
// first index of each cell, cells in the grid's order, with one more entry at the end.
template <int D>
struct CellGridView {
  static constexpr int kReach = 1;  // cells scanned on each side of a particle's cell
  Real lo[D] = {};
  Real cell_size = 0;  // the search radius: every particle within it of a query is a candidate
  Real inverse_cell_size = 0;
  int counts[D] = {};  // including kReach padding cells on each side
  const std::uint32_t* cell_start = nullptr;

  // The cell of coordinate `value` along axis a, clamped to the interior so that all scanned
  // cells exist.
  SLUICE_HOST_DEVICE int axis_cell(int a, Real value) const {
    const Real offset = (value - lo[a]) * inverse_cell_size;
    const Real count = counts[a];
    const int k = (offset < 0 ? 0 : static_cast<int>(offset < count ? offset : count)) + kReach;
    return k < counts[a] - 1 - kReach ? k : counts[a] - 1 - kReach;
  }
  SLUICE_HOST_DEVICE void cell_coords(const Real* x, int* c) const {
    for (int a = 0; a < D; ++a) c[a] = axis_cell(a, x[a]);
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

  // Calls fn(begin, end) for the contiguous index ranges that hold every particle within a cell
  // size of x (and some farther ones): the three cells of each row along x next to x's cell.
  template <class Fn>
  SLUICE_HOST_DEVICE void for_each_candidate_range(const Real* x, Fn&& fn) const {
    int c[D];
    cell_coords(x, c);
    for_each_row(c, [&](std::uint32_t row_start, const int*) {
      fn(cell_start[row_start + c[0] - kReach], cell_start[row_start + c[0] + kReach + 1]);
    });
  }

  // The same ranges clipped to the search sphere: along each row, only the cells from x - w to
  // x + w, w the half chord of the sphere at the row's nearest face; rows it does not reach are
  // skipped. That costs a square root a row, worth it only where every candidate costs much (the
  // WCSPH pair loops; a scan that only tests distances was measured slower). With kWidenTo > 1
  // each range is widened within its row to a multiple of kWidenTo particles where the row has
  // them, for SIMD loops to which farther particles add exactly nothing.
  template <int kWidenTo = 1, class Fn>
  SLUICE_HOST_DEVICE void for_each_clipped_range(const Real* x, Fn&& fn) const {
    int c[D];
    cell_coords(x, c);
    // A margin for rounding, so that a particle at the radius is never lost to it.
    const Real reach2 = cell_size * cell_size * Real(1.000001);
    for_each_row(c, [&](std::uint32_t row_start, const int* offset) {
      Real chord2 = reach2;
      for (int a = D - 1; a > 0; --a) chord2 -= gap2(a, c[a], offset[a], x[a]);
      scan_row<kWidenTo>(x[0], row_start, chord2, fn);
    });
  }

 private:
  // Calls row(first cell of the row, offset) for the rows along x next to cell c: offset[a] is
  // the row's offset from c along axis a > 0 (3 rows in 2D, 9 in 3D).
  template <class RowFn>
  SLUICE_HOST_DEVICE void for_each_row(const int* c, RowFn&& row) const {
    for (int dz = -kReach; dz <= kReach; ++dz) {
      if constexpr (D == 2) {
        const int offset[2] = {0, dz};
        row(linear(0, c[1] + dz, 0), offset);
      } else {
        for (int dy = -kReach; dy <= kReach; ++dy) {
          const int offset[3] = {0, dy, dz};
          row(linear(0, c[1] + dy, c[2] + dz), offset);
        }
      }
    }
  }
  // The squared distance along axis a from coordinate v in cell k to the cell `offset` away:
  // zero for its own cell; from the face between them, which a particle clamped into a border
  // cell lies beyond too.
  SLUICE_HOST_DEVICE Real gap2(int a, int k, int offset, Real v) const {
    if (offset == 0) return 0;
    const Real face = lo[a] + (k - kReach + (offset > 0 ? offset : offset + 1)) * cell_size;
    const Real gap = offset > 0 ? face - v : v - face;
    return gap > 0 ? gap * gap : 0;
  }
  // The part of the row starting at index row_start within sqrt(chord2) of x along x.
  template <int kWidenTo, class Fn>
  SLUICE_HOST_DEVICE void scan_row(Real x, std::uint32_t row_start, Real chord2, Fn& fn) const {
    if (chord2 <= 0) return;
    const Real half = std::sqrt(chord2);
    std::uint32_t begin = cell_start[row_start + axis_cell(0, x - half)];
    std::uint32_t end = cell_start[row_start + axis_cell(0, x + half) + 1];
    if constexpr (kWidenTo > 1) {
      const std::uint32_t row_begin = cell_start[row_start];
      const std::uint32_t row_end = cell_start[row_start + counts[0]];
      const std::uint32_t wide = (end - begin + kWidenTo - 1) / kWidenTo * kWidenTo;
      end = begin + wide < row_end ? begin + wide : row_end;
      begin = end - row_begin > wide ? end - wide : row_begin;
    }
    fn(begin, end);
  }
};

// The grid of cells of edge `radius` that covers [lo, hi], padded by kReach cells on each side
// (without cell starts), and into `cells` its count of cells.
template <int D>
CellGridView<D> cell_grid_over(const Vec<D>& lo, const Vec<D>& hi, Real radius, std::size_t& cells);

template <int D>
class CellList {
 public:
  CellList() = default;
  // Cells of edge `radius` cover [lo, hi]; positions outside are clamped to the border
  // cells, so a stray particle is still found (the divergence guard reports it).
  CellList(const Vec<D>& lo, const Vec<D>& hi, Real radius);

  // Sorts particles by cell: fills `order` (new index k holds old particle order[k]).
  // Call reorder on the particle set with it, then `positions` are sorted. With `gone`, the
  // particles i for which gone[i] holds are left out of `order` (a rank's ghosts of the last
  // step and the particles it sent away), and reorder drops them.
  void sort(const std::vector<Vec<D>>& positions, std::vector<std::uint32_t>& order,
            const std::vector<bool>* gone = nullptr);

  Real radius() const { return grid_.cell_size; }
  std::size_t cell_count() const { return cell_start_.size() - 1; }
  // The grid with the cells of the last sort.
  CellGridView<D> view() const {
    CellGridView<D> v = grid_;
    v.cell_start = cell_start_.data();
    return v;
  }

  // Checkpoints: the cells of the last sort (the particles have moved since).
  void archive_state(StateArchive& a) { a(cell_start_); }
  const std::vector<std::uint32_t>& cell_starts() const { return cell_start_; }
  // The cells of a sort made elsewhere (a device's, over the same grid): particles of cell c
  // are [start[c], start[c + 1]).
  void assign_cell_starts(std::vector<std::uint32_t> start) { cell_start_ = std::move(start); }

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
  std::vector<std::uint32_t>
      cell_start_;                      // particles of cell c: [cell_start_[c], cell_start_[c+1])
  std::vector<std::uint32_t> cell_of_;  // scratch: cell of each particle before sorting
};

}  // namespace sluice
