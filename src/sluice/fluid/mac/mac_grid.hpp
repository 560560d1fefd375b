// The staggered marker-and-cell grid (Harlow & Welch 1965): pressure and level set at cell
// centres, each velocity component on the faces normal to its axis. Index 0 runs fastest.
// A `Lattice` is any of these arrangements (the cells, or the faces of one axis) with the
// multilinear sampling that advection and the probes use.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "sluice/core/state_archive.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

template <int D>
using GridIndex = std::array<int, D>;

// Points in a regular arrangement: `dims` of them along each axis, `h` apart, the first at
// `first`.
template <int D>
struct Lattice {
  GridIndex<D> dims{};
  Vec<D> first = Vec<D>::Zero();
  Real h = 1;
  // The axis along which the lattice repeats every dims points (a periodic grid's), or -1. Along
  // it every coordinate is held: index() takes its remainder, and sample() reads across the seam.
  int wrap_axis = -1;

  std::size_t size() const {
    std::size_t n = 1;
    for (int a = 0; a < D; ++a) n *= static_cast<std::size_t>(dims[a]);
    return n;
  }
  std::size_t index(GridIndex<D> c) const {
    if (wrap_axis >= 0) {
      const int n = dims[wrap_axis];
      c[wrap_axis] = (c[wrap_axis] % n + n) % n;
    }
    std::size_t k = 0;
    for (int a = D - 1; a >= 0; --a) k = k * static_cast<std::size_t>(dims[a]) + c[a];
    return k;
  }
  GridIndex<D> coordinates(std::size_t k) const {
    GridIndex<D> c;
    for (int a = 0; a < D; ++a) {
      c[a] = static_cast<int>(k % static_cast<std::size_t>(dims[a]));
      k /= static_cast<std::size_t>(dims[a]);
    }
    return c;
  }
  bool contains(const GridIndex<D>& c) const {
    for (int a = 0; a < D; ++a)
      if (a != wrap_axis && (c[a] < 0 || c[a] >= dims[a])) return false;
    return true;
  }
  // Distance between neighbours along `axis` in the storage.
  std::size_t stride(int axis) const {
    std::size_t s = 1;
    for (int a = 0; a < axis; ++a) s *= static_cast<std::size_t>(dims[a]);
    return s;
  }
  Vec<D> position(const GridIndex<D>& c) const {
    Vec<D> x = first;
    for (int a = 0; a < D; ++a) x[a] += c[a] * h;
    return x;
  }

  // Multilinear interpolation of `values` at x, the point clamped into the lattice grown by
  // `reach` spacings (beyond the lattice: linear extrapolation); `low` and `high` receive the
  // smallest and largest of the 2^D values used (MacCormack's limiter).
  Real sample(const std::vector<Real>& values, const Vec<D>& x, Real* low = nullptr,
              Real* high = nullptr, Real reach = 0) const {
    // Two instances, so that the plain sample (most calls: velocities) keeps no range.
    return low != nullptr || high != nullptr ? sample_in<true>(values, x, low, high, reach)
                                             : sample_in<false>(values, x, low, high, reach);
  }

 private:
  template <bool kRange>
  Real sample_in(const std::vector<Real>& values, const Vec<D>& x, Real* low, Real* high,
                 Real reach) const {
    GridIndex<D> base;
    std::array<Real, D> t;
    for (int a = 0; a < D; ++a) {
      if (a == wrap_axis) {
        const Real s = (x[a] - first[a]) / h;
        base[a] = static_cast<int>(std::floor(s));
        t[a] = s - base[a];
        continue;
      }
      const Real s = std::clamp((x[a] - first[a]) / h, -reach, Real(dims[a] - 1) + reach);
      base[a] = std::clamp(static_cast<int>(std::floor(s)), 0, std::max(dims[a] - 2, 0));
      t[a] = dims[a] > 1 ? s - base[a] : 0;
    }
    // The corners as offsets in the storage from the base's index: base[a] + 1 stays inside
    // wherever dims[a] > 1 (the clamp above), stays put where dims[a] == 1, and along the wrap
    // axis is taken by index() across the seam.
    const std::size_t k0 = index(base);
    std::array<std::ptrdiff_t, D> step;
    for (int a = 0; a < D; ++a) {
      if (a == wrap_axis) {
        GridIndex<D> next = base;
        next[a] += 1;
        step[a] = static_cast<std::ptrdiff_t>(index(next)) - static_cast<std::ptrdiff_t>(k0);
      } else {
        step[a] = dims[a] > 1 ? static_cast<std::ptrdiff_t>(stride(a)) : 0;
      }
    }
    Real sum = 0;
    [[maybe_unused]] Real lo = 1e300, hi = -1e300;  // the range, where kRange
    for (int corner = 0; corner < (1 << D); ++corner) {
      std::ptrdiff_t offset = 0;
      Real w = 1;
      for (int a = 0; a < D; ++a) {
        const bool up = (corner >> a) & 1;
        if (up) offset += step[a];
        w *= up ? t[a] : 1 - t[a];
      }
      const Real v = values[static_cast<std::size_t>(static_cast<std::ptrdiff_t>(k0) + offset)];
      sum += w * v;
      if constexpr (kRange) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    }
    if constexpr (kRange) {
      if (low != nullptr) *low = lo;
      if (high != nullptr) *high = hi;
    }
    return sum;
  }
};

template <int D>
struct MacGrid {
  GridIndex<D> cells{};
  Vec<D> origin = Vec<D>::Zero();  // the lower corner of the first cell
  Real h = 1;                      // the cells' edge
  // The axis whose two sides are joined (a periodic case's), or -1: along it the last cell's
  // upper face is the first cell's lower one, and every lattice repeats.
  int periodic_axis = -1;

  Lattice<D> cell_lattice() const {
    return {cells, origin + Vec<D>::Constant(0.5 * h), h, periodic_axis};
  }
  // The faces normal to `axis`: one more than the cells along it, on the cells' walls (as many
  // along the periodic axis, the last face being the first).
  Lattice<D> face_lattice(int axis) const {
    Lattice<D> l = cell_lattice();
    if (axis != periodic_axis) l.dims[axis] += 1;
    l.first[axis] = origin[axis];
    return l;
  }
  // The cells' corners.
  Lattice<D> node_lattice() const {
    Lattice<D> l{cells, origin, h, periodic_axis};
    for (int a = 0; a < D; ++a)
      if (a != periodic_axis) l.dims[a] += 1;
    return l;
  }
  // Whether the faces of `axis` at coordinate c along it lie on the grid's boundary (never
  // along the periodic axis).
  bool on_boundary(int axis, int c) const {
    return axis != periodic_axis && (c == 0 || c == cells[axis]);
  }
  // x brought into the grid's span along the periodic axis, where it left it.
  Vec<D> wrapped(Vec<D> x) const {
    if (periodic_axis < 0) return x;
    const Real length = cells[periodic_axis] * h;
    Real& c = x[periodic_axis];
    c -= length * std::floor((c - origin[periodic_axis]) / length);
    return x;
  }
  std::size_t cell_count() const { return cell_lattice().size(); }
};

// Calls visit(axis, side, cell, face) for each face on the grid's boundary (none along the
// periodic axis; side 0 at the lower end, 1 at the upper) with the index of the cell inside it
// and the face's index in its axis's face lattice. Serial: the boundary holds few faces.
template <int D, class Visit>
void for_each_boundary_face(const MacGrid<D>& grid, Visit&& visit) {
  const Lattice<D> cells = grid.cell_lattice();
  for (int a = 0; a < D; ++a) {
    if (a == grid.periodic_axis) continue;
    const Lattice<D> faces = grid.face_lattice(a);
    Lattice<D> plane = cells;  // one side's cells: a layer one cell thick across axis a
    plane.dims[a] = 1;
    for (const int side : {0, 1}) {
      for (std::size_t j = 0; j < plane.size(); ++j) {
        GridIndex<D> c = plane.coordinates(j);
        c[a] = side == 0 ? 0 : grid.cells[a] - 1;
        GridIndex<D> face = c;
        face[a] += side;
        visit(a, side, cells.index(c), faces.index(face));
      }
    }
  }
}

// The share of a cell that the level set's surface leaves in the water (a smeared step of
// width h).
inline Real water_fraction(Real phi, Real h) {
  return std::clamp(0.5 - phi / h, 0.0, 1.0);
}

// A value per cell, and one per face of each axis.
using CellField = std::vector<Real>;
template <int D>
using FaceField = std::array<std::vector<Real>, D>;

template <int D>
FaceField<D> make_face_field(const MacGrid<D>& grid, Real value = 0) {
  FaceField<D> f;
  for (int a = 0; a < D; ++a) f[a].assign(grid.face_lattice(a).size(), value);
  return f;
}

// The velocity at x from the face components.
template <int D>
Vec<D> velocity_at(const MacGrid<D>& grid, const std::type_identity_t<FaceField<D>>& u,
                   const Vec<D>& x) {
  Vec<D> v;
  for (int a = 0; a < D; ++a) v[a] = grid.face_lattice(a).sample(u[a], x);
  return v;
}

}  // namespace sluice
