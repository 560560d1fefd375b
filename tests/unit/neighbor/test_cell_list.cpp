// The cell-linked list finds exactly the pairs a brute-force search finds, including points
// that lie on cell faces or outside its grid, and sorting keeps every particle. Its clipped
// candidate ranges hold fewer particles, and, widened or not, every neighbour once and nothing
// outside their row.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "sluice/neighbor/cell_list.hpp"

namespace sluice {
namespace {

// With `shrink` > 0 the grid covers only the middle of the points' box, so that some points and
// some queries lie outside it.
template <int D>
void check_against_brute_force(std::vector<Vec<D>> points, Real radius, Real shrink = 0) {
  Vec<D> lo = Vec<D>::Constant(1e9), hi = Vec<D>::Constant(-1e9);
  for (const auto& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Vec<D> margin = shrink * (hi - lo);
  CellList<D> cells(lo + margin, hi - margin, radius);
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

TEST(CellList, PointsOutsideTheGridAreFoundToo2D) {
  check_against_brute_force<2>(random_points<2>(2000, 4), 0.11, 0.3);
}
TEST(CellList, PointsOutsideTheGridAreFoundToo3D) {
  check_against_brute_force<3>(random_points<3>(3000, 5), 0.23, 0.3);
}

TEST(CellList, PointsOutsideTheGridAreClampedNotLost) {
  std::vector<Vec<3>> points = random_points<3>(500, 3);
  points.push_back(Vec<3>(5.0, -4.0, 0.5));  // outside the grid built below
  CellList<3> cells(Vec<3>::Constant(-0.3), Vec<3>::Constant(1.7), 0.2);
  std::vector<std::uint32_t> order;
  cells.sort(points, order);
  EXPECT_EQ(std::set<std::uint32_t>(order.begin(), order.end()).size(), points.size());
}

TEST(CellList, ASortLeavesOutTheParticlesThatAreGone) {
  const std::vector<Vec<2>> points = random_points<2>(300, 7);
  std::vector<bool> gone(points.size());
  for (std::size_t i = 0; i < gone.size(); ++i) gone[i] = i % 3 == 1;
  CellList<2> cells(Vec<2>::Zero(), Vec<2>::Ones(), 0.1);
  std::vector<std::uint32_t> all, kept;
  cells.sort(points, all);
  cells.sort(points, kept, &gone);
  // The same order with the gone ones taken out, and cells that count only the rest.
  std::vector<std::uint32_t> expected;
  for (const std::uint32_t i : all) {
    if (!gone[i]) expected.push_back(i);
  }
  EXPECT_EQ(kept, expected);
  EXPECT_EQ(cells.cell_starts().back(), expected.size());
}

// The clipped candidate ranges of every point, widened to multiples of W, against the brute-force
// neighbours: each neighbour is a candidate once, and a range's length is a multiple of W
// unless it spans its whole row of cells.
template <int D, int W>
void check_widened_ranges(const std::vector<Vec<D>>& points, Real radius) {
  CellList<D> cells(Vec<D>::Zero(), Vec<D>::Ones(), radius);
  std::vector<std::uint32_t> order;
  cells.sort(points, order);
  std::vector<Vec<D>> sorted(points.size());
  for (std::size_t k = 0; k < order.size(); ++k) sorted[k] = points[order[k]];
  const CellGridView<D> grid = cells.view();
  auto row_of = [&](std::size_t k) { return grid.cell_of(sorted[k].data()) / grid.counts[0]; };
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    std::vector<int> seen(sorted.size(), 0);
    grid.template for_each_clipped_range<W>(sorted[i].data(), [&](std::uint32_t begin,
                                                                  std::uint32_t end) {
      if (begin == end) return;
      EXPECT_EQ(row_of(begin), row_of(end - 1)) << "a range left its row";
      const bool whole_row = (begin == 0 || row_of(begin - 1) != row_of(begin)) &&
                             (end == sorted.size() || row_of(end) != row_of(end - 1));
      EXPECT_TRUE((end - begin) % W == 0 || whole_row) << "range [" << begin << ", " << end << ")";
      for (std::uint32_t j = begin; j < end; ++j) ++seen[j];
    });
    for (std::size_t j = 0; j < sorted.size(); ++j) {
      ASSERT_LE(seen[j], 1) << "candidate " << j << " of " << i << " twice";
      if ((sorted[i] - sorted[j]).squaredNorm() < radius * radius) {
        ASSERT_EQ(seen[j], 1) << "neighbour " << j << " of " << i << " missed";
      }
    }
  }
}

TEST(CellList, ClippedRangesKeepEveryNeighbourOnceAndStayInTheirRow) {
  const auto points = random_points<3>(3000, 6);
  check_widened_ranges<3, 1>(points, 0.23);  // clipped only
  check_widened_ranges<3, 8>(points, 0.23);
  check_widened_ranges<3, 5>(points, 0.23);
  const auto flat = random_points<2>(2000, 7);
  check_widened_ranges<2, 1>(flat, 0.11);
  check_widened_ranges<2, 8>(flat, 0.11);
}

// Clipped, a query scans the cells its sphere reaches in each row, not the whole 3x3x3 cube of
// cells that the plain ranges hold (the sphere itself holds 0.155 of the cube).
TEST(CellList, CandidatesAreClippedToTheSearchSphere) {
  const Real dx = 0.02, radius = 3 * dx;
  std::vector<Vec<3>> points;
  for (int i = 0; i < 50; ++i)
    for (int j = 0; j < 50; ++j)
      for (int k = 0; k < 50; ++k) points.emplace_back(i * dx + 0.01, j * dx + 0.01, k * dx + 0.01);
  CellList<3> cells(Vec<3>::Zero(), Vec<3>::Ones(), radius);
  std::vector<std::uint32_t> order;
  cells.sort(points, order);
  std::vector<Vec<3>> sorted(points.size());
  for (std::size_t k = 0; k < order.size(); ++k) sorted[k] = points[order[k]];
  double candidates = 0, whole = 0, neighbours = 0, interior = 0;
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    if ((sorted[i].array() < 0.2).any() || (sorted[i].array() > 0.8).any()) continue;
    ++interior;
    cells.view().for_each_clipped_range(
        sorted[i].data(),
        [&](std::uint32_t begin, std::uint32_t end) { candidates += end - begin; });
    cells.for_each_candidate_range(
        sorted[i], [&](std::uint32_t begin, std::uint32_t end) { whole += end - begin; });
    cells.for_each_neighbor(sorted, i, radius * radius,
                            [&](std::size_t, const Vec<3>&, Real) { ++neighbours; });
  }
  const double cube = std::pow(3 * radius / dx, 3);  // the 27 whole cells' particles
  EXPECT_NEAR(whole / interior, cube, 1e-9);
  EXPECT_LT(candidates / interior, 0.9 * cube);  // 0.84 here
  EXPECT_GT(candidates / interior, neighbours / interior);
}

}  // namespace
}  // namespace sluice
