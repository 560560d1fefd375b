// The cell-linked list finds exactly the pairs a brute-force search finds, including points
// that lie on cell faces, and sorting keeps every particle.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "sluice/neighbor/cell_list.hpp"

namespace sluice {
namespace {

template <int D>
void check_against_brute_force(std::vector<Vec<D>> points, Real radius) {
  Vec<D> lo = Vec<D>::Constant(1e9), hi = Vec<D>::Constant(-1e9);
  for (const auto& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  CellList<D> cells(lo, hi, radius);
  std::vector<std::uint32_t> order;
  cells.sort(points, order);
  ASSERT_EQ(order.size(), points.size());
  std::vector<Vec<D>> sorted(points.size());
  for (std::size_t k = 0; k < order.size(); ++k) sorted[k] = points[order[k]];
  std::set<std::uint32_t> unique(order.begin(), order.end());
  ASSERT_EQ(unique.size(), points.size()) << "sorting lost or duplicated particles";

  const Real r2max = radius * radius;
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    std::vector<std::size_t> found;
    cells.for_each_neighbor(sorted, i, r2max, [&](std::size_t j, const Vec<D>& rij, Real r2) {
      EXPECT_NEAR((sorted[i] - sorted[j] - rij).norm(), 0.0, 1e-15);
      EXPECT_NEAR(rij.squaredNorm(), r2, 1e-15);
      found.push_back(j);
    });
    std::vector<std::size_t> expected;
    for (std::size_t j = 0; j < sorted.size(); ++j) {
      if (j != i && (sorted[i] - sorted[j]).squaredNorm() < r2max) expected.push_back(j);
    }
    std::sort(found.begin(), found.end());
    ASSERT_EQ(found, expected) << "particle " << i;
  }
}

template <int D>
std::vector<Vec<D>> random_points(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-0.3, 1.7);
  std::vector<Vec<D>> points(n);
  for (auto& p : points) {
    for (int a = 0; a < D; ++a) p[a] = u(rng);
  }
  return points;
}

// Points exactly on the faces of cells of size `radius` starting at 0, and at the corners.
template <int D>
std::vector<Vec<D>> face_points(Real radius) {
  std::vector<Vec<D>> points;
  for (int k = 0; k < 400; ++k) {
    Vec<D> p;
    for (int a = 0; a < D; ++a) p[a] = ((k * (a + 3)) % 7) * radius * (a == k % D ? 1.0 : 0.5);
    points.push_back(p);
  }
  return points;
}

TEST(CellList, MatchesBruteForce2D) {
  check_against_brute_force<2>(random_points<2>(2000, 1), 0.11);
}
TEST(CellList, MatchesBruteForce3D) {
  check_against_brute_force<3>(random_points<3>(3000, 2), 0.23);
}
TEST(CellList, PointsOnCellFaces2D) {
  check_against_brute_force<2>(face_points<2>(0.1), 0.1);
}
TEST(CellList, PointsOnCellFaces3D) {
  check_against_brute_force<3>(face_points<3>(0.1), 0.1);
}

TEST(CellList, PointsOutsideTheGridAreClampedNotLost) {
  std::vector<Vec<3>> points = random_points<3>(500, 3);
  points.push_back(Vec<3>(5.0, -4.0, 0.5));  // outside the grid built below
  CellList<3> cells(Vec<3>::Constant(-0.3), Vec<3>::Constant(1.7), 0.2);
  std::vector<std::uint32_t> order;
  cells.sort(points, order);
  EXPECT_EQ(std::set<std::uint32_t>(order.begin(), order.end()).size(), points.size());
}

}  // namespace
}  // namespace sluice
