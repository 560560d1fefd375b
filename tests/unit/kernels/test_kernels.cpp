// Kernel operators: normalisation, zero mean gradient, and the SPH gradient of a linear field
// on a regular lattice, for both kernels in 2D and 3D.
#include <gtest/gtest.h>

#include <cmath>

#include "sluice/kernels/cubic_spline.hpp"
#include "sluice/kernels/wendland_c2.hpp"

namespace sluice {
namespace {

// Midpoint-rule integral over [-2h, 2h]^D of value(r) and of grad W = r * gradient_factor(r).
template <int D, class Kernel>
std::pair<double, Vec<D>> integrate(const Kernel& kernel, int cells_per_axis) {
  const double lo = -kernel.support(), step = 2 * kernel.support() / cells_per_axis;
  const double volume = std::pow(step, D);
  double sum = 0;
  Vec<D> gradient = Vec<D>::Zero();
  const long total = static_cast<long>(std::pow(cells_per_axis, D));
  for (long k = 0; k < total; ++k) {
    Vec<D> x;
    long rest = k;
    for (int a = 0; a < D; ++a) {
      x[a] = lo + (rest % cells_per_axis + 0.5) * step;
      rest /= cells_per_axis;
    }
    const double r = x.norm();
    sum += kernel.value(r) * volume;
    gradient += x * kernel.gradient_factor(r) * volume;
  }
  return {sum, gradient};
}

template <class KernelT>
class KernelTest : public ::testing::Test {};

template <int D, template <int> class K>
struct KernelCase {
  static constexpr int kDim = D;
  using Kernel = K<D>;
};

using Kernels = ::testing::Types<KernelCase<2, WendlandC2>, KernelCase<3, WendlandC2>,
                                 KernelCase<2, CubicSpline>, KernelCase<3, CubicSpline>>;
TYPED_TEST_SUITE(KernelTest, Kernels);

TYPED_TEST(KernelTest, IntegratesToOne) {
  constexpr int D = TypeParam::kDim;
  const typename TypeParam::Kernel kernel(0.013);
  const auto [sum, gradient] = integrate<D>(kernel, D == 2 ? 400 : 120);
  EXPECT_NEAR(sum, 1.0, 1e-3);
  EXPECT_LT(gradient.norm() * kernel.h, 1e-9);
}

TYPED_TEST(KernelTest, GradientFactorMatchesFiniteDifference) {
  const typename TypeParam::Kernel kernel(0.5);
  for (double r : {0.05, 0.3, 0.49, 0.51, 0.8, 0.99}) {
    const double e = 1e-6;
    const double derivative = (kernel.value(r + e) - kernel.value(r - e)) / (2 * e);
    EXPECT_NEAR(kernel.gradient_factor(r) * r, derivative, 1e-6 * std::abs(kernel.norm))
        << "r = " << r;
  }
  EXPECT_EQ(kernel.value(1.0), 0.0);
  EXPECT_EQ(kernel.gradient_factor(1.0), 0.0);
}

TYPED_TEST(KernelTest, BranchlessFormsMatch) {
  const typename TypeParam::Kernel kernel(0.5);
  for (double r = 0; r < 1.2; r += 0.01) {
    EXPECT_NEAR(kernel.value_branchless(float(r)), kernel.value(r), 2e-6 * kernel.norm) << r;
    EXPECT_NEAR(kernel.gradient_factor_branchless(float(r)), kernel.gradient_factor(r),
                2e-5 * kernel.norm / (kernel.h * kernel.h))
        << r;
  }
}

// grad phi_i = sum_j V_j (phi_j - phi_i) grad W_ij for phi = a . x on a regular lattice with
// the kernel's default h/dx: exact within 1 % at an interior particle.
TYPED_TEST(KernelTest, GradientOfLinearFieldOnLattice) {
  constexpr int D = TypeParam::kDim;
  const double dx = 0.01;
  using Kernel = typename TypeParam::Kernel;
  const Kernel kernel(Kernel::kDefaultHOverDx * dx);
  Vec<D> a;
  for (int k = 0; k < D; ++k) a[k] = 1.0 + 0.7 * k;
  const double volume = std::pow(dx, D);
  const int reach = 4;
  Vec<D> gradient = Vec<D>::Zero();
  const Vec<D> xi = Vec<D>::Zero();  // an interior lattice particle
  const int width = 2 * reach + 1;
  const long total = static_cast<long>(std::pow(width, D));
  for (long k = 0; k < total; ++k) {
    Vec<D> xj;
    long rest = k;
    for (int c = 0; c < D; ++c) {
      xj[c] = ((rest % width) - reach) * dx;
      rest /= width;
    }
    const Vec<D> r_ij = xi - xj;
    const double r = r_ij.norm();
    if (r == 0) continue;
    gradient += volume * (a.dot(xj) - a.dot(xi)) * kernel.gradient_factor(r) * r_ij;
  }
  for (int c = 0; c < D; ++c) EXPECT_NEAR(gradient[c], a[c], 0.01 * a[c]) << "component " << c;
}

}  // namespace
}  // namespace sluice
