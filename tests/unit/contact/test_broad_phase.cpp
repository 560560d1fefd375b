#include "sluice/contact/broad_phase.hpp"

#include <gtest/gtest.h>

#include <random>

namespace sluice {
namespace {

std::vector<BodyPair> brute_force(const std::vector<AxisBox>& boxes, const std::vector<bool>& fixed,
                                  double margin) {
  std::vector<BodyPair> pairs;
  for (std::uint32_t a = 0; a < boxes.size(); ++a) {
    for (std::uint32_t b = a + 1; b < boxes.size(); ++b) {
      if (fixed[a] && fixed[b]) continue;
      if (boxes[a].overlaps(boxes[b], margin)) pairs.emplace_back(a, b);
    }
  }
  return pairs;
}

// Debris of mixed sizes in a tank, with its six sides as large fixed bodies and one plane.
TEST(BroadPhase, FindsTheSamePairsAsEveryPairTested) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> where(0.0, 2.0), size(0.01, 0.08);
  std::vector<AxisBox> boxes;
  std::vector<bool> fixed, large;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 lo(where(random), where(random), 0.5 * where(random));
    boxes.push_back({lo, lo + Vec3(size(random), size(random), size(random))});
    fixed.push_back(k % 50 == 0);
    large.push_back(false);
  }
  for (int side = 0; side < 6; ++side) {
    AxisBox wall{Vec3(-0.1, -0.1, -0.1), Vec3(2.1, 2.1, 1.1)};
    (side % 2 ? wall.min : wall.max)[side / 2] = (side % 2 ? wall.max : wall.min)[side / 2];
    boxes.push_back(wall);
    fixed.push_back(true);
    large.push_back(false);  // found large by their size
  }
  boxes.push_back({Vec3(-1, -1, -1), Vec3(3, 3, 0.2)});
  fixed.push_back(true);
  large.push_back(true);
  BroadPhase broad;
  std::vector<BodyPair> pairs;
  for (double margin : {0.0, 0.01, 0.05}) {
    broad.find(boxes, fixed, large, margin, pairs);
    const auto expected = brute_force(boxes, fixed, margin);
    EXPECT_GT(expected.size(), 500u);
    EXPECT_EQ(pairs, expected) << "margin " << margin;
  }
}

TEST(BroadPhase, BodiesWithoutParticlesAndFewBodies) {
  BroadPhase broad;
  std::vector<BodyPair> pairs;
  broad.find({AxisBox{Vec3::Zero(), Vec3::Ones()}}, {false}, {false}, 0.1, pairs);
  EXPECT_TRUE(pairs.empty());
  const std::vector<AxisBox> boxes{AxisBox{Vec3::Zero(), Vec3::Ones()}, AxisBox::empty(),
                                   AxisBox{Vec3::Constant(1.05), Vec3::Constant(2)}};
  broad.find(boxes, {false, false, false}, {false, false, false}, 0.1, pairs);
  EXPECT_EQ(pairs, (std::vector<BodyPair>{{0, 2}}));
}

}  // namespace
}  // namespace sluice
