// The MPS weight function and the constants of a full particle lattice that the MPS operators
// are normalised by (Koshizuka & Oka 1996): the particle number density n0 and the Laplacian
// model's lambda.
#pragma once

#include <algorithm>
#include <cmath>

#include "sluice/core/host_device.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

// w(r) = r_e / r - 1 for r < r_e, else 0. It grows without bound as r -> 0, which keeps
// particles apart; r is floored at 1e-6 r_e so that two coincident particles stay finite.
struct MpsWeight {
  Real re = 0;

  SLUICE_HOST_DEVICE Real operator()(Real r) const {
    if (r >= re) return 0;
    return re / std::max(r, 1e-6 * re) - 1;
  }
};

// Sums over the neighbours of one particle of an unbounded square (2D) or cubic (3D) lattice of
// spacing l0: n0 = sum w(|r|), lambda = sum |r|^2 w / sum w, and how many neighbours lie
// within r_e.
struct MpsLatticeConstants {
  Real n0 = 0;
  Real lambda = 0;
  int neighbours = 0;
};

template <int D>
MpsLatticeConstants full_lattice_constants(Real spacing, Real re) {
  const MpsWeight w{re};
  const int reach = static_cast<int>(std::ceil(re / spacing));
  MpsLatticeConstants c;
  Real r2w = 0;
  for (int i = -reach; i <= reach; ++i) {
    for (int j = -reach; j <= reach; ++j) {
      for (int k = (D == 3 ? -reach : 0); k <= (D == 3 ? reach : 0); ++k) {
        if (i == 0 && j == 0 && k == 0) continue;
        const Real r2 = spacing * spacing * static_cast<Real>(i * i + j * j + k * k);
        const Real r = std::sqrt(r2);
        if (r >= re) continue;
        c.n0 += w(r);
        r2w += r2 * w(r);
        ++c.neighbours;
      }
    }
  }
  c.lambda = r2w / c.n0;
  return c;
}

}  // namespace sluice
