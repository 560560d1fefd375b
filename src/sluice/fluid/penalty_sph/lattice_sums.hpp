// Sums of Müller et al.'s kernels over a full lattice of spacing dx around one particle: what a
// particle deep in still water sees on the lattice the fluid starts on. The penalty-sph model
// corrects its summed density and reads its still-water pressure by them.
#pragma once

#include <cmath>

#include "sluice/core/types.hpp"
#include "sluice/kernels/muller_kernels.hpp"

namespace sluice {

// sum over the lattice points x_j = dx (a, b[, c]) within the support of term(x_j), the particle
// itself (x_j = 0) included.
template <int D, class Term>
Real sum_over_lattice(const MullerKernels<D>& kernels, Real dx, Term term) {
  const int n = static_cast<int>(std::ceil(kernels.h / dx));
  Real sum = 0;
  for (int a = -n; a <= n; ++a) {
    for (int b = -n; b <= n; ++b) {
      for (int c = (D == 3 ? -n : 0); c <= (D == 3 ? n : 0); ++c) {
        Vec<D> x;
        if constexpr (D == 2) {
          x << a, b;
        } else {
          x << a, b, c;
        }
        sum += term(Vec<D>(dx * x));
      }
    }
  }
  return sum;
}

// sum_j W_poly6(|x_j|): a full lattice's summed density over its particles' mass.
template <int D>
Real lattice_poly6_sum(const MullerKernels<D>& kernels, Real dx) {
  return sum_over_lattice<D>(kernels, dx, [&](const Vec<D>& x) { return kernels.poly6(x.norm()); });
}

// The gain G with which sum_j V_j (p_j - p_i) grad W_spiky measures the gradient of a linear
// pressure on a full lattice (V_j = dx^D): -sum_j V_j W'(r)/r x_j x_j^T = G I. It is below one
// at Müller et al.'s short support, so still water's pressure p = k (rho - rho0) rises by
// rho g / G per metre to hold its weight.
template <int D>
Real lattice_gradient_gain(const MullerKernels<D>& kernels, Real dx) {
  return sum_over_lattice<D>(kernels, dx, [&](const Vec<D>& x) {
    return -std::pow(dx, D) * kernels.spiky_gradient_factor(x.norm()) * x[0] * x[0];
  });
}

}  // namespace sluice
