#include "sluice/fluid/mac/level_set.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sluice/exec/policy.hpp"

namespace sluice {

namespace {

// Signed distance to a box (negative inside).
template <int D>
Real box_distance(const Vec<D>& lo, const Vec<D>& hi, const Vec<D>& x) {
  Real outside = 0, inside = -std::numeric_limits<Real>::infinity();
  for (int a = 0; a < D; ++a) {
    const Real q = std::max(lo[a] - x[a], x[a] - hi[a]);
    if (q > 0) outside += q * q;
    inside = std::max(inside, q);
  }
  return outside > 0 ? std::sqrt(outside) : std::min(inside, Real(0));
}

// Solution of the upwind discretisation of |grad d| = 1 from the smallest neighbour distance
// along each axis (`a` sorted ascending).
template <int D>
Real eikonal_update(std::array<Real, D> a, Real h) {
  std::sort(a.begin(), a.end());
  Real d = a[0] + h;
  if (D >= 2 && d > a[1]) {
    d = 0.5 *
        (a[0] + a[1] + std::sqrt(std::max(Real(0), 2 * h * h - (a[0] - a[1]) * (a[0] - a[1]))));
  }
  if constexpr (D == 3) {
    if (d > a[2]) {
      const Real s = a[0] + a[1] + a[2];
      const Real s2 = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
      d = (s + std::sqrt(std::max(Real(0), s * s - 3 * (s2 - h * h)))) / 3;
    }
  }
  return d;
}

}  // namespace

template <int D>
CellField level_set_of_blocks(const MacGrid<D>& grid, const std::vector<AxisBox>& blocks,
                              const AxisBox& domain) {
  const Lattice<D> cells = grid.cell_lattice();
  const Vec<D> domain_lo = from_3d<D>(domain.min), domain_hi = from_3d<D>(domain.max);
  const Real far = 1e3 * (domain_hi - domain_lo).norm();
  std::vector<std::pair<Vec<D>, Vec<D>>> boxes;
  for (const AxisBox& b : blocks) {
    Vec<D> lo = from_3d<D>(b.min), hi = from_3d<D>(b.max);
    const Real touch = 1e-9 * far;
    for (int a = 0; a < D; ++a) {
      if (lo[a] <= domain_lo[a] + touch) lo[a] = -far;
      if (hi[a] >= domain_hi[a] - touch) hi[a] = far;
    }
    boxes.emplace_back(lo, hi);
  }
  CellField phi(cells.size(), far);
  exec::Default::for_each(phi.size(), [&](std::size_t k) {
    const Vec<D> x = cells.position(cells.coordinates(k));
    for (const auto& [lo, hi] : boxes) phi[k] = std::min(phi[k], box_distance<D>(lo, hi, x));
  });
  return phi;
}

template <int D>
void reinitialise(const MacGrid<D>& grid, CellField& phi, int rounds) {
  const Lattice<D> cells = grid.cell_lattice();
  const Real h = grid.h;
  const Real infinity = std::numeric_limits<Real>::infinity();
  std::vector<Real> d(phi.size(), infinity);
  std::vector<char> fixed(phi.size(), 0);
  // A cell beside a sign change keeps |phi| / |grad phi| (central differences): the distance
  // to the plane that phi's first-order expansion puts its zero on, never more than the
  // nearest crossing along an axis.
  exec::Default::for_each(phi.size(), [&](std::size_t k) {
    const GridIndex<D> c = cells.coordinates(k);
    Real nearest = infinity, gradient2 = 0;
    for (int a = 0; a < D; ++a) {
      std::array<Real, 2> value{phi[k], phi[k]};
      int spread = 0;
      for (const int side : {0, 1}) {
        GridIndex<D> n = c;
        n[a] += side == 0 ? -1 : 1;
        if (!cells.contains(n)) continue;
        const Real other = phi[cells.index(n)];
        value[side] = other;
        ++spread;
        if ((phi[k] < 0) != (other < 0)) nearest = std::min(nearest, h * phi[k] / (phi[k] - other));
      }
      if (spread > 0) {
        const Real slope = (value[1] - value[0]) / (spread * h);
        gradient2 += slope * slope;
      }
    }
    if (nearest < infinity) {
      d[k] = gradient2 > 0 ? std::min(nearest, std::abs(phi[k]) / std::sqrt(gradient2)) : nearest;
      fixed[k] = 1;
    }
  });
  for (int round = 0; round < rounds; ++round) {
    for_each_sweep<D>(cells, [&](std::size_t k, const GridIndex<D>& c) {
      if (fixed[k]) return;
      std::array<Real, D> a;
      for (int axis = 0; axis < D; ++axis) {
        a[axis] = infinity;
        for (const int side : {-1, 1}) {
          GridIndex<D> n = c;
          n[axis] += side;
          if (cells.contains(n)) a[axis] = std::min(a[axis], d[cells.index(n)]);
        }
      }
      if (*std::min_element(a.begin(), a.end()) < infinity)
        d[k] = std::min(d[k], eikonal_update<D>(a, h));
    });
  }
  exec::Default::for_each_light(phi.size(), [&](std::size_t k) {
    if (d[k] < infinity) phi[k] = phi[k] < 0 ? -d[k] : d[k];
  });
}

template CellField level_set_of_blocks<2>(const MacGrid<2>&, const std::vector<AxisBox>&,
                                          const AxisBox&);
template CellField level_set_of_blocks<3>(const MacGrid<3>&, const std::vector<AxisBox>&,
                                          const AxisBox&);
template void reinitialise<2>(const MacGrid<2>&, CellField&, int);
template void reinitialise<3>(const MacGrid<3>&, CellField&, int);

}  // namespace sluice
