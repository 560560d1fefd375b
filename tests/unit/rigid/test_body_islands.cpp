#include "sluice/rigid/body_islands.hpp"

#include <gtest/gtest.h>

namespace sluice {
namespace {

TEST(BodyIslands, PairsAndJointsTieBodiesAndFixedBodiesTieNone) {
  // 0 and 2 touch, 3 is joined to 4, 1 is a wall that 0 and 3 rest on, 5 is alone; a joint of 5
  // to the world (an index past the last body) ties nothing.
  const std::vector<bool> fixed{false, true, false, false, false, false};
  const std::vector<IslandPair> pairs{{0, 2}, {0, 1}, {1, 3}};
  const std::vector<IslandPair> joints{{3, 4}, {5, 99}};
  const std::vector<int> island = body_islands(fixed, pairs, joints);
  EXPECT_EQ(island, (std::vector<int>{0, -1, 0, 1, 1, 2}));
}

TEST(BodyIslands, AChainIsOneIslandNumberedByItsLowestBody) {
  const std::vector<bool> fixed(5, false);
  // 4-3, 3-1, 1-2 chain, given out of order; 0 alone.
  const std::vector<int> island = body_islands(fixed, {{3, 4}, {1, 3}, {1, 2}}, {});
  EXPECT_EQ(island, (std::vector<int>{0, 1, 1, 1, 1}));
}

TEST(IslandRanks, HeaviestFirstToTheLeastLoadedRank) {
  // 5 -> rank 0; 4 -> 1; 3 -> 1 (4 < 5); 3 -> 0 (5 < 7); 3 -> 1 (7 < 8).
  EXPECT_EQ(island_ranks({5, 4, 3, 3, 3}, 2), (std::vector<int>{0, 1, 1, 0, 1}));
  // Equal work: in island order, the lower rank first.
  EXPECT_EQ(island_ranks({1, 1, 1}, 3), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(island_ranks({1, 2}, 1), (std::vector<int>{0, 0}));
  EXPECT_TRUE(island_ranks({}, 4).empty());
}

}  // namespace
}  // namespace sluice
