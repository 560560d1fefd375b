#include "sluice/parallel/decomposition.hpp"

#include <gtest/gtest.h>

#include <array>
#include <limits>
#include <vector>

#include "sluice/parallel/rcb_partition.hpp"

namespace sluice {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Four boxes in 2D as RCB draws them: cut at x = 1, then each half at its own y (0.5 left, 2
// right); the outer sides open.
Decomposition four_boxes() {
  std::vector<RankBox> boxes(4);
  boxes[0] = {{-kInf, -kInf, 0}, {1, 0.5, 0}};
  boxes[1] = {{-kInf, 0.5, 0}, {1, kInf, 0}};
  boxes[2] = {{1, -kInf, 0}, {kInf, 2, 0}};
  boxes[3] = {{1, 2, 0}, {kInf, kInf, 0}};
  return Decomposition(2, boxes);
}

using P = std::array<double, 2>;

TEST(Decomposition, EachPointHasOneBoxWithItsLowerFacesAndOpenEnds) {
  const Decomposition d = four_boxes();
  EXPECT_FALSE(d.is_slabs());
  EXPECT_EQ(d.ranks(), 4);
  EXPECT_EQ(d.owner(P{-100, -100}), 0);
  EXPECT_EQ(d.owner(P{0.999, 0.499}), 0);
  EXPECT_EQ(d.owner(P{0.999, 0.5}), 1);  // a face belongs to the box above it
  EXPECT_EQ(d.owner(P{1.0, 0.5}), 2);
  EXPECT_EQ(d.owner(P{1.0, 2.0}), 3);
  EXPECT_EQ(d.owner(P{100, 100}), 3);
  EXPECT_EQ(d.owner(P{-100, 100}), 1);
}

TEST(Decomposition, GhostsGoToEveryOtherBoxWithinTheDepth) {
  const Decomposition d = four_boxes();
  const auto near = [&](P x, double depth, int self) {
    std::vector<int> ranks;
    d.for_each_rank_near(x, depth, self, [&](int r) { ranks.push_back(r); });
    return ranks;
  };
  EXPECT_EQ(near(P{0, 0}, 0.3, 0), std::vector<int>{});
  EXPECT_EQ(near(P{0, 0.3}, 0.3, 0), std::vector<int>{1});
  EXPECT_EQ(near(P{0.8, 0.3}, 0.3, 0), (std::vector<int>{1, 2}));
  EXPECT_EQ(near(P{0.8, 1.9}, 0.3, 1), (std::vector<int>{2, 3}));  // a corner of three others
  EXPECT_EQ(near(P{1.5, 2.5}, 0.3, 3), std::vector<int>{});
}

TEST(Decomposition, SlabsAnswerAsTheirCutsDo) {
  const Decomposition d(SlabDecomposition(1, {1.0, 2.0}));
  EXPECT_TRUE(d.is_slabs());
  EXPECT_EQ(d.ranks(), 3);
  EXPECT_EQ(d.owner(P{50, 1.5}), 1);
  std::vector<int> near;
  d.for_each_rank_near(P{-50, 1.9}, 0.2, 1, [&](int r) { near.push_back(r); });
  EXPECT_EQ(near, std::vector<int>{2});
  EXPECT_EQ(d.describe(), "3 slabs along y, cut at 1, 2 m");
}

TEST(Decomposition, RegionsComeBackAsTheyWent) {
  const Decomposition boxes = four_boxes();
  const Decomposition read = boxes.with_regions(boxes.regions());
  ASSERT_EQ(read.ranks(), 4);
  for (const P x : {P{0.5, 0.2}, P{0.5, 0.7}, P{3, 1}, P{3, 3}, P{1, 2}}) {
    EXPECT_EQ(read.owner(x), boxes.owner(x));
  }
  EXPECT_EQ(boxes.regions().size(), 16u);  // lower and upper corner, two axes, four boxes
  EXPECT_THROW(boxes.with_regions({1, 2, 3}), std::runtime_error);
  const Decomposition slabs(SlabDecomposition(0, {0.5}));
  EXPECT_EQ(slabs.with_regions({0.7}).slabs().cuts(), std::vector<double>{0.7});
  EXPECT_EQ(boxes.describe(), "4 boxes by recursive coordinate bisection (Zoltan RCB)");
}

TEST(Decomposition, RcbOnOneRankIsOneBoxOfAllSpace) {
  if (!rcb_offered()) GTEST_SKIP() << "this build has no Zoltan";
  const std::vector<double> points{0, 0, 1, 1, 2, 0.5}, work{1, 1, 0.1};
  const Decomposition d = rcb_boxes(Communicator::alone(), 2, points, work);
  EXPECT_EQ(d.ranks(), 1);
  EXPECT_EQ(d.owner(P{-1e300, 1e300}), 0);
  const std::vector<double> one_weight{1.0};
  EXPECT_THROW(rcb_boxes(Communicator::alone(), 2, points, one_weight), std::logic_error);
}

}  // namespace
}  // namespace sluice
