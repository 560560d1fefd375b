#include "sluice/contact/contact_set.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace sluice {
namespace {

ParticlePair pair_along(const Vec3& normal, double overlap = 1e-4) {
  return {Vec3::Zero(), normal.normalized(), overlap, 1e-4};
}

TEST(ContactSet, PairsGroupByNormalPerBodyPair) {
  ContactSet set;
  set.begin_pass();
  set.add(0, 1, pair_along(Vec3::UnitZ()));    // on the floor
  set.add(0, 1, pair_along(Vec3(0.1, 0, 1)));  // 6 degrees off: the same contact
  set.add(0, 1, pair_along(Vec3::UnitX()));    // against a side: another
  set.add(0, 2, pair_along(Vec3::UnitZ()));    // another body pair
  set.end_pass();
  const auto& contacts = set.contacts();
  ASSERT_EQ(contacts.size(), 3u);
  EXPECT_EQ(contacts[0].pairs.size(), 2u);
  EXPECT_EQ(contacts[1].pairs.size(), 1u);
  EXPECT_EQ(contacts[2].b, 2u);
  EXPECT_NEAR(contacts[0].normal.norm(), 1.0, 1e-12);
  EXPECT_NE(contacts[0].id, contacts[1].id);
  EXPECT_NE(contacts[1].id, contacts[2].id);
}

// A contact whose normal turns by 5 degrees a pass, from +x through 45 degrees to +z, keeps
// its identity and tangential history all the way.
TEST(ContactSet, ATurningContactKeepsItsHistory) {
  ContactSet set;
  std::uint64_t id = 0;
  for (int pass = 0; pass <= 18; ++pass) {
    const double angle = pass * 5.0 * std::numbers::pi / 180;
    set.begin_pass();
    set.add(0, 1, pair_along(Vec3(std::cos(angle), 0, std::sin(angle))));
    set.end_pass();
    ASSERT_EQ(set.contacts().size(), 1u);
    Contact& c = set.contacts()[0];
    if (pass == 0) {
      id = c.id;
      EXPECT_EQ(c.tangential, Vec3::Zero());
    } else {
      EXPECT_EQ(c.id, id) << "pass " << pass;
      EXPECT_EQ(c.tangential, Vec3(pass, 0, 0)) << "pass " << pass;
    }
    c.tangential = Vec3(pass + 1, 0, 0);
  }
}

TEST(ContactSet, AnEndedContactForgetsAndAJumpStartsAfresh) {
  ContactSet set;
  set.begin_pass();
  set.add(0, 1, pair_along(Vec3::UnitZ()));
  set.end_pass();
  set.contacts()[0].tangential = Vec3(1, 2, 0);
  const std::uint64_t first = set.contacts()[0].id;
  // A normal 90 degrees away is another contact, not this one turned.
  set.begin_pass();
  set.add(0, 1, pair_along(Vec3::UnitX()));
  set.end_pass();
  EXPECT_NE(set.contacts()[0].id, first);
  EXPECT_EQ(set.contacts()[0].tangential, Vec3::Zero());
  // A pass without the bodies touching, then touching again: a new contact.
  set.begin_pass();
  set.end_pass();
  set.begin_pass();
  set.add(0, 1, pair_along(Vec3::UnitZ()));
  set.end_pass();
  EXPECT_EQ(set.contacts()[0].tangential, Vec3::Zero());
  EXPECT_NE(set.contacts()[0].id, first);
}

TEST(ContactSet, WeightedPointAndDeepestOverlap) {
  ContactSet set;
  set.begin_pass();
  ParticlePair shallow = pair_along(Vec3::UnitZ(), 1e-4), deep = pair_along(Vec3::UnitZ(), 4e-4);
  shallow.point = Vec3(0, 0, 0);
  deep.point = Vec3(1, 0, 0);
  set.add(3, 4, shallow);
  set.add(3, 4, deep);
  set.end_pass();
  const Contact& c = set.contacts()[0];
  EXPECT_DOUBLE_EQ(c.overlap, 4e-4);
  EXPECT_DOUBLE_EQ(c.area, 2e-4);
  // Weights overlap^(3/2): 1 and 8.
  EXPECT_NEAR(c.point[0], 8.0 / 9.0, 1e-12);
}

}  // namespace
}  // namespace sluice
