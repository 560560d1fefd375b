// The MPS weight, the full-lattice constants and the operators (fluid/mps/mps_operators.hpp)
// on regular lattices, where each has a closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "mps_lattice.hpp"
#include "sluice/fluid/mps/mps_operators.hpp"

namespace sluice {
namespace {

TEST(MpsWeight, ValueAndSupport) {
  const MpsWeight w{2.1};
  EXPECT_DOUBLE_EQ(w(1.0), 1.1);
  EXPECT_DOUBLE_EQ(w(2.0), 2.1 / 2.0 - 1);
  EXPECT_EQ(w(2.1), 0.0);
  EXPECT_EQ(w(3.0), 0.0);
  EXPECT_TRUE(std::isfinite(w(0.0)));  // coincident particles stay finite
  EXPECT_GT(w(0.5), w(1.0));           // and repel more the closer they are
}

// 2D, r_e = 2.1 l0: 4 neighbours at l0, 4 at sqrt(2) l0, 4 at 2 l0.
TEST(MpsLattice, ConstantsOfTheSquareLatticeInClosedForm) {
  const double l0 = 0.01, re = 2.1 * l0;
  const MpsLatticeConstants c = full_lattice_constants<2>(l0, re);
  const double w1 = 2.1 - 1, w2 = 2.1 / std::sqrt(2.0) - 1, w4 = 2.1 / 2 - 1;
  const double n0 = 4 * (w1 + w2 + w4);
  EXPECT_EQ(c.neighbours, 12);
  EXPECT_NEAR(c.n0, n0, 1e-12);
  EXPECT_NEAR(c.lambda, l0 * l0 * 4 * (1 * w1 + 2 * w2 + 4 * w4) / n0, 1e-18);
}

// 3D, r_e = 2.1 l0: 6 at l0, 12 at sqrt(2) l0, 8 at sqrt(3) l0, 6 at 2 l0.
TEST(MpsLattice, ConstantsOfTheCubicLatticeInClosedForm) {
  const double l0 = 1, re = 2.1;
  const MpsLatticeConstants c = full_lattice_constants<3>(l0, re);
  const double w1 = re - 1, w2 = re / std::sqrt(2.0) - 1, w3 = re / std::sqrt(3.0) - 1,
               w4 = re / 2 - 1;
  const double n0 = 6 * w1 + 12 * w2 + 8 * w3 + 6 * w4;
  EXPECT_EQ(c.neighbours, 32);
  EXPECT_NEAR(c.n0, n0, 1e-12);
  EXPECT_NEAR(c.lambda, (6 * w1 + 24 * w2 + 24 * w3 + 24 * w4) / n0, 1e-12);
}

template <int D>
void number_density_of_full_lattice_is_n0() {
  const double l0 = 0.02, re = 2.1 * l0;
  MpsTestLattice<D> lattice(4, l0, re);
  const MpsLatticeConstants c = full_lattice_constants<D>(l0, re);
  const MpsOperators<D> op(lattice.x, lattice.neighbours, MpsWeight{re}, c);
  int count = 0;
  const double n = op.number_density(
      lattice.centre, [](std::size_t) { return true; }, count);
  EXPECT_NEAR(n, c.n0, 1e-9 * c.n0);
  EXPECT_EQ(count, c.neighbours);
}

TEST(MpsOperators, NumberDensityOfAFullLatticeIsN0) {
  number_density_of_full_lattice_is_n0<2>();
  number_density_of_full_lattice_is_n0<3>();
}

// lap |x|^2 = 2d, and the MPS Laplacian gives it exactly on a full lattice: the linear part
// cancels by symmetry and the rest is lambda n0 by lambda's definition.
template <int D>
void laplacian_of_quadratic_field() {
  const double l0 = 0.02, re = 3.1 * l0;
  MpsTestLattice<D> lattice(5, l0, re);
  const MpsOperators<D> op(lattice.x, lattice.neighbours, MpsWeight{re},
                           full_lattice_constants<D>(l0, re));
  std::vector<Real> f;
  for (const auto& x : lattice.x) f.push_back(x.squaredNorm() + 3 * x[0] - 1);
  const Real lap = op.laplacian(lattice.centre, f, [](std::size_t) { return true; });
  EXPECT_NEAR(lap, 2.0 * D, 1e-9);
}

TEST(MpsOperators, LaplacianOfAQuadraticFieldIsExactOnTheLattice) {
  laplacian_of_quadratic_field<2>();
  laplacian_of_quadratic_field<3>();
}

// The Laplacian on its own, wider radius (4.0 l0, Koshizuka & Oka 1996) over a neighbour list
// of that radius: still exact for the quadratic field, while the number density keeps the
// 2.1 l0 radius and its n0.
template <int D>
void laplacian_on_its_own_radius() {
  const double l0 = 0.02, re = 2.1 * l0, wide = 4.0 * l0;
  MpsTestLattice<D> lattice(6, l0, wide);
  const MpsLatticeConstants c = full_lattice_constants<D>(l0, re);
  const MpsOperators<D> op(lattice.x, lattice.neighbours, MpsWeight{re}, c, MpsWeight{wide},
                           full_lattice_constants<D>(l0, wide), true);
  std::vector<Real> f;
  for (const auto& x : lattice.x) f.push_back(x.squaredNorm() - 2 * x[D - 1]);
  const auto all = [](std::size_t) { return true; };
  EXPECT_NEAR(op.laplacian(lattice.centre, f, all), 2.0 * D, 1e-9);
  int count = 0;
  EXPECT_NEAR(op.number_density(lattice.centre, all, count), c.n0, 1e-9 * c.n0);
  EXPECT_EQ(count, c.neighbours);
  // The coefficient is the wide weight's: nonzero at 3 l0, where the narrow weight is zero.
  std::size_t far = lattice.centre;
  for (std::size_t j = 0; j < lattice.x.size(); ++j) {
    if (std::abs((lattice.x[j] - lattice.x[lattice.centre]).norm() - 3 * l0) < 1e-9) far = j;
  }
  ASSERT_NE(far, lattice.centre);
  EXPECT_GT(op.laplacian_coefficient(lattice.centre, far), 0);
}

TEST(MpsOperators, LaplacianOnItsOwnWiderRadius) {
  laplacian_on_its_own_radius<2>();
  laplacian_on_its_own_radius<3>();
}

// A linear field: the plain gradient is exact on the full lattice; on a stretched lattice (still
// symmetric, so p-hat shifts nothing) only the corrected one is.
template <int D>
void gradient_of_linear_field(bool stretched) {
  const double l0 = 0.02, re = 2.1 * l0;
  MpsTestLattice<D> lattice(4, l0, re);
  if (stretched) {
    for (auto& x : lattice.x) x[0] *= 0.9;  // closer along x: more neighbours that way
  }
  Vec<D> g;
  g.setLinSpaced(2.0, 5.0);
  std::vector<Real> p;
  for (const auto& x : lattice.x) p.push_back(1000 + g.dot(x));
  const auto all = [](std::size_t) { return true; };
  const MpsLatticeConstants c = full_lattice_constants<D>(l0, re);
  const MpsOperators<D> corrected(lattice.x, lattice.neighbours, MpsWeight{re}, c, true);
  const MpsOperators<D> plain(lattice.x, lattice.neighbours, MpsWeight{re}, c, false);
  EXPECT_LT((corrected.gradient(lattice.centre, p, all) - g).norm(), 1e-9 * g.norm());
  const double plain_error = (plain.gradient(lattice.centre, p, all) - g).norm();
  if (stretched) {
    EXPECT_GT(plain_error, 0.05 * g.norm());
  } else {
    EXPECT_LT(plain_error, 1e-9 * g.norm());
  }
}

TEST(MpsOperators, GradientOfALinearField) {
  gradient_of_linear_field<2>(false);
  gradient_of_linear_field<3>(false);
  gradient_of_linear_field<2>(true);
  gradient_of_linear_field<3>(true);
}

TEST(MpsOperators, DivergenceOfALinearVelocityField) {
  const double l0 = 0.02, re = 2.1 * l0;
  MpsTestLattice<3> lattice(4, l0, re);
  const MpsOperators<3> op(lattice.x, lattice.neighbours, MpsWeight{re},
                           full_lattice_constants<3>(l0, re));
  std::vector<Vec<3>> u;
  for (const auto& x : lattice.x) u.push_back(Vec<3>(2 * x[0], -0.5 * x[1], 3 * x[2] + x[0]));
  EXPECT_NEAR(op.divergence(lattice.centre, u, [](std::size_t) { return true; }), 4.5, 1e-9);
}

}  // namespace
}  // namespace sluice
