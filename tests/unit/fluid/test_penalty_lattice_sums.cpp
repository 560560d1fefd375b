// The lattice sums of penalty-sph's kernels (fluid/penalty_sph/lattice_sums.hpp): the gradient
// gain G is what the SPH difference gradient measures of a linear field on the lattice, in any
// direction; both sums become the continuous kernel's integrals when the support spans many
// spacings.
#include <gtest/gtest.h>

#include "sluice/fluid/penalty_sph/lattice_sums.hpp"
#include "sluice/fluid/penalty_sph/penalty_sph_parameters.hpp"

namespace sluice {
namespace {

// sum_j dx^D (p_j - p_0) grad W(x_0 - x_j) for p = slope . x, over an explicit block of lattice
// points wider than the support.
template <int D>
Vec<D> difference_gradient(const MullerKernels<D>& kernels, Real dx, const Vec<D>& slope) {
  const int n = static_cast<int>(kernels.h / dx) + 2;
  Vec<D> sum = Vec<D>::Zero();
  for (int a = -n; a <= n; ++a) {
    for (int b = -n; b <= n; ++b) {
      for (int c = (D == 3 ? -n : 0); c <= (D == 3 ? n : 0); ++c) {
        Vec<D> xj;
        if constexpr (D == 2) {
          xj << dx * a, dx * b;
        } else {
          xj << dx * a, dx * b, dx * c;
        }
        const Vec<D> r0j = -xj;  // x_0 - x_j
        sum += std::pow(dx, D) * slope.dot(xj) * kernels.spiky_gradient_factor(r0j.norm()) * r0j;
      }
    }
  }
  return sum;
}

template <int D>
void expect_gain_measures_a_linear_field(const Vec<D>& slope) {
  const Real dx = 0.04;
  const MullerKernels<D> kernels(PenaltySphParameters{}.smoothing_length(dx, D));
  const Real gain = lattice_gradient_gain(kernels, dx);
  EXPECT_GT(gain, 0.5);
  EXPECT_LT(gain, 1.0);  // Müller et al.'s support of about 20 particles measures short
  const Vec<D> measured = difference_gradient(kernels, dx, slope);
  EXPECT_NEAR((measured - gain * slope).norm(), 0, 1e-9 * slope.norm()) << measured.transpose();
}

TEST(PenaltyLatticeSums, GradientGainIsWhatTheDifferenceGradientMeasures) {
  expect_gain_measures_a_linear_field<2>(Vec<2>(0.3, -9.81));
  expect_gain_measures_a_linear_field<3>(Vec<3>(0.3, -1.2, -9.81));
}

TEST(PenaltyLatticeSums, BecomeTheKernelsIntegralsOverAWideSupport) {
  const Real dx = 0.01;
  const MullerKernels<2> wide2(8 * dx);
  const MullerKernels<3> wide3(8 * dx);
  // sum_j dx^D W(x_j) -> integral of W = 1; G -> 1.
  EXPECT_NEAR(lattice_poly6_sum(wide2, dx) * dx * dx, 1.0, 0.01);
  EXPECT_NEAR(lattice_poly6_sum(wide3, dx) * dx * dx * dx, 1.0, 0.01);
  EXPECT_NEAR(lattice_gradient_gain(wide2, dx), 1.0, 0.01);
  EXPECT_NEAR(lattice_gradient_gain(wide3, dx), 1.0, 0.01);
}

}  // namespace
}  // namespace sluice
