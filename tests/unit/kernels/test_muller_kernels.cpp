// Müller, Charypar & Gross's kernels (kernels/muller_kernels.hpp) in 2D and 3D: poly6 and spiky
// integrate to one, the gradients and the poly6 Laplacian are the derivatives of the values,
// and the viscosity Laplacian gives lap(x^2) = 2 in the continuum.
#include <gtest/gtest.h>

#include <cmath>

#include "sluice/kernels/muller_kernels.hpp"

namespace sluice {
namespace {

// Midpoint rule over [-h, h]^D of f(x).
template <int D, class F>
double integrate(double h, int cells, F&& f) {
  const double step = 2 * h / cells, volume = std::pow(step, D);
  double sum = 0;
  const long total = static_cast<long>(std::pow(cells, D));
  for (long k = 0; k < total; ++k) {
    Vec<D> x;
    long rest = k;
    for (int a = 0; a < D; ++a) {
      x[a] = -h + (rest % cells + 0.5) * step;
      rest /= cells;
    }
    sum += f(x) * volume;
  }
  return sum;
}

template <int D>
void kernels_are_normalised_and_consistent() {
  const double h = 0.05;
  const MullerKernels<D> k(h);
  const int cells = D == 2 ? 400 : 100;
  EXPECT_NEAR(integrate<D>(h, cells, [&](const Vec<D>& x) { return k.poly6(x.norm()); }), 1, 2e-3);
  EXPECT_NEAR(integrate<D>(h, cells, [&](const Vec<D>& x) { return k.spiky(x.norm()); }), 1, 2e-3);
  // The continuum Laplacian with the viscosity kernel: integral of (f(x) - f(0)) lap W for
  // f = x_0^2 is lap f = 2.
  EXPECT_NEAR(
      integrate<D>(h, cells,
                   [&](const Vec<D>& x) { return x[0] * x[0] * k.viscosity_laplacian(x.norm()); }),
      2, 4e-3);
  // Derivatives against central differences of the values, across the support.
  for (double q : {0.1, 0.35, 0.6, 0.85}) {
    const double r = q * h, e = 1e-6 * h, e2 = 1e-3 * h;  // a wider step for the second
    const double d1 = (k.poly6(r + e) - k.poly6(r - e)) / (2 * e);
    const double d2 = (k.poly6(r + e2) - 2 * k.poly6(r) + k.poly6(r - e2)) / (e2 * e2);
    const double lap = k.poly6_laplacian(r);
    EXPECT_NEAR(k.poly6_gradient_factor(r) * r, d1, 1e-6 * std::abs(d1)) << q;
    EXPECT_NEAR(lap, d2 + (D - 1) * d1 / r, 1e-5 * std::abs(lap)) << q;
    const double s1 = (k.spiky(r + e) - k.spiky(r - e)) / (2 * e);
    EXPECT_NEAR(k.spiky_gradient_factor(r) * r, s1, 1e-6 * std::abs(s1)) << q;
  }
  EXPECT_EQ(k.poly6(h), 0);
  EXPECT_EQ(k.spiky_gradient_factor(0), 0);
  EXPECT_EQ(k.viscosity_laplacian(1.01 * h), 0);
}

TEST(MullerKernels, NormalisedAndConsistentIn2D) {
  kernels_are_normalised_and_consistent<2>();
}
TEST(MullerKernels, NormalisedAndConsistentIn3D) {
  kernels_are_normalised_and_consistent<3>();
}

}  // namespace
}  // namespace sluice
