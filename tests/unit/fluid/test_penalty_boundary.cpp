// Seed 002's boundary force on one fluid particle (fluid/penalty_sph/penalty_boundary.hpp),
// worked by hand from equation (9): f_np = (Ks d - (v . n) Kd) n.
#include <gtest/gtest.h>

#include "sluice/fluid/penalty_sph/penalty_boundary.hpp"

namespace sluice {
namespace {

const PenaltyLaw kLaw{5e4, 2.0};  // Ks = 5e4 N/m, Kd = 2 N s/m
constexpr Real kReach = 0.006;    // solid spacing 0.002 m, fluid 0.01 m: (0.002 + 0.01) / 2

TEST(PenaltyBoundary, PressedIntoASolidParticleByHand) {
  // 1 mm inside the reach, straight above, falling at 0.5 m/s:
  // d = 0.001 m, n = +z, v . n = -0.5 m/s, f = 5e4 * 0.001 + 0.5 * 2 = 51 N up.
  const Vec3 xb(0.05, 0.05, 0.1), x = xb + Vec3(0, 0, 0.005), v(0, 0, -0.5);
  const auto c = penalty_contact<3>(kLaw, x, x + Vec3(0, 0, 0.001), v, xb, Vec3::Zero(), kReach);
  EXPECT_FALSE(c.crossed);
  EXPECT_NEAR(c.depth, 0.001, 1e-15);
  EXPECT_NEAR(c.force.z(), 51.0, 1e-9);
  EXPECT_NEAR(c.force.head<2>().norm(), 0.0, 1e-15);
  // At an angle: the force lies along the line of centres, with the same depth.
  const Vec3 slanted = xb + 0.005 * Vec3(0.6, 0, 0.8);
  const auto s = penalty_contact<3>(kLaw, slanted, slanted, Vec3::Zero(), xb, Vec3::Zero(), kReach);
  EXPECT_NEAR(s.depth, 0.001, 1e-15);
  EXPECT_NEAR((s.force - 50.0 * Vec3(0.6, 0, 0.8)).norm(), 0.0, 1e-9);
  // A solid moving with the fluid adds no damping.
  const auto moving = penalty_contact<3>(kLaw, x, x, v, xb, v, kReach);
  EXPECT_NEAR(moving.force.z(), 50.0, 1e-9);
}

TEST(PenaltyBoundary, NoForceOutsideTheReachAndNeverAPull) {
  const Vec<2> xb(0, 0), x(0, 0.0061);
  EXPECT_EQ(penalty_contact<2>(kLaw, x, x, Vec<2>(0, -1), xb, Vec<2>::Zero(), kReach).depth, 0);
  // Leaving at 10 m/s from 0.1 mm deep: 5e4 * 1e-4 - 2 * 10 < 0 would pull; zero instead.
  const Vec<2> inside(0, 0.0059);
  const auto leaving =
      penalty_contact<2>(kLaw, inside, inside, Vec<2>(0, 10), xb, Vec<2>::Zero(), kReach);
  EXPECT_GT(leaving.depth, 0);
  EXPECT_EQ(leaving.force.norm(), 0);
}

TEST(PenaltyBoundary, ACrossingWithinOneStepIsPushedBackTheWayItCame) {
  // From 8 mm above to 2 mm below within one step: past the centre, so the normal is the one
  // above and d = reach + 2 mm = 8 mm; the force points up.
  const Vec3 xb(0, 0, 0), before(0, 0, 0.008), after(0.0005, 0, -0.002);
  const auto c = penalty_contact<3>(kLaw, after, before, Vec3(0, 0, -1), xb, Vec3::Zero(), kReach);
  EXPECT_TRUE(c.crossed);
  EXPECT_NEAR(c.depth, kReach + 0.002, 1e-12);
  EXPECT_NEAR(c.force.z(), 5e4 * c.depth + 2.0, 1e-9);
  // A path that passes beside the solid particle, outside the reach, is no crossing.
  const Vec3 beside_before(0.007, 0, 0.008), beside_after(0.007, 0, -0.008);
  const auto miss = penalty_contact<3>(kLaw, beside_after, beside_before, Vec3(0, 0, -1), xb,
                                       Vec3::Zero(), kReach);
  EXPECT_FALSE(miss.crossed);
  EXPECT_EQ(miss.depth, 0);
}

}  // namespace
}  // namespace sluice
