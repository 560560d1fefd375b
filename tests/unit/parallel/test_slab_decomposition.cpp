#include "sluice/parallel/slab_decomposition.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace sluice {
namespace {

TEST(SlabDecomposition, EachCoordinateHasOneOwnerWithOpenEnds) {
  const SlabDecomposition slabs(0, {1.0, 2.0});
  EXPECT_EQ(slabs.ranks(), 3);
  EXPECT_EQ(slabs.owner(-100.0), 0);
  EXPECT_EQ(slabs.owner(0.999), 0);
  EXPECT_EQ(slabs.owner(1.0), 1);  // a cut belongs to the slab above it
  EXPECT_EQ(slabs.owner(1.999), 1);
  EXPECT_EQ(slabs.owner(2.0), 2);
  EXPECT_EQ(slabs.owner(100.0), 2);
}

TEST(SlabDecomposition, GhostsGoToEveryOtherRankWithinTheDepth) {
  const SlabDecomposition slabs(1, {1.0, 1.2, 3.0});
  const auto near = [&](double x, double depth, int self) {
    std::vector<int> ranks;
    slabs.for_each_rank_near(x, depth, self, [&](int r) { ranks.push_back(r); });
    return ranks;
  };
  EXPECT_EQ(near(0.5, 0.3, 0), std::vector<int>{});
  EXPECT_EQ(near(0.8, 0.3, 0), std::vector<int>{1});
  EXPECT_EQ(near(0.8, 0.45, 0), (std::vector<int>{1, 2}));  // the slab of rank 1 is thinner
  EXPECT_EQ(near(1.1, 0.05, 1), std::vector<int>{});
  EXPECT_EQ(near(2.9, 0.2, 2), std::vector<int>{3});
  EXPECT_EQ(near(3.1, 0.2, 3), std::vector<int>{2});
}

TEST(SlabDecomposition, BalancedSlabsShareTheParticlesAndCutBetweenLatticePlanes) {
  // Ten planes of a lattice at x = 0.05, 0.15, ..., 0.95, four particles each.
  std::vector<double> x;
  for (int plane = 0; plane < 10; ++plane) {
    for (int k = 0; k < 4; ++k) x.push_back(0.05 + 0.1 * plane);
  }
  const SlabDecomposition halves = balanced_slabs(x, {}, 0, 2);
  ASSERT_EQ(halves.cuts().size(), 1u);
  EXPECT_NEAR(halves.cuts()[0], 0.5, 1e-12);
  const SlabDecomposition fifths = balanced_slabs(x, {}, 0, 5);
  ASSERT_EQ(fifths.cuts().size(), 4u);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(fifths.cuts()[k], 0.2 * (k + 1), 1e-12);
  // A share that ends inside a plane moves to the plane's far side: no plane is cut.
  const SlabDecomposition thirds = balanced_slabs(x, {}, 0, 3);
  for (const double cut : thirds.cuts()) {
    const double planes = (cut - 0.05) / 0.1;
    EXPECT_NEAR(planes - std::floor(planes), 0.5, 1e-9) << "cut at " << cut;
  }
  EXPECT_EQ(balanced_slabs(x, {}, 0, 1).ranks(), 1);
}

TEST(SlabDecomposition, BalancedSlabsShareTheWeights) {
  // Particles at 0.5, 1.5, ..., 9.5; the last five weigh four times the first five.
  std::vector<double> x, w;
  for (int k = 0; k < 10; ++k) {
    x.push_back(k + 0.5);
    w.push_back(k < 5 ? 1.0 : 4.0);
  }
  const SlabDecomposition halves = balanced_slabs(x, w, 0, 2);
  ASSERT_EQ(halves.cuts().size(), 1u);
  // Half the weight is 12.5: the five light ones and the heavy one at 5.5 make 9, the next
  // would make 13, so the cut falls between 5.5 and 6.5.
  EXPECT_NEAR(halves.cuts()[0], 6.0, 1e-12);
}

TEST(SlabDecomposition, DescribesItsCuts) {
  EXPECT_EQ(SlabDecomposition(1, {0.5, 1.25}).describe(), "3 slabs along y, cut at 0.5, 1.25 m");
  EXPECT_EQ(SlabDecomposition().describe(), "one slab");
}

}  // namespace
}  // namespace sluice
