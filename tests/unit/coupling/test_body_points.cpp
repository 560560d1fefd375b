// Points fixed in bodies: rigid motion (position, velocity, acceleration) and the wrench that
// forces on them add up to.
#include "sluice/coupling/body_points.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace sluice {
namespace {

BodyKinematics turning_body() {
  BodyKinematics m;
  m.position = Vec3(0.5, 0.5, 0.5);
  m.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi / 6, Vec3::UnitZ()));
  m.velocity = Vec3(1, 0, 0);
  m.angular_velocity = Vec3(0, 0, 2);
  m.acceleration = Vec3(0, 0, -1);
  m.angular_acceleration = Vec3(0, 3, 0);
  return m;
}

TEST(BodyPoints, MoveRigidly) {
  const BodyPoints points({{0, Vec3(0.1, 0, 0)}, {0, Vec3(0, 0.2, -0.1)}, {0, Vec3::Zero()}});
  const std::vector<BodyKinematics> motion{turning_body()};
  const BodyKinematics& m = motion[0];
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Vec3 r = points.position(k, motion) - m.position;
    EXPECT_NEAR(r.norm(), points[k].local.norm(), 1e-15);
    EXPECT_NEAR((points.velocity(k, motion) - (m.velocity + m.angular_velocity.cross(r))).norm(), 0,
                1e-15);
    const Vec3 expected = m.acceleration + m.angular_acceleration.cross(r) +
                          m.angular_velocity.cross(m.angular_velocity.cross(r));
    EXPECT_NEAR((points.acceleration(k, motion) - expected).norm(), 0, 1e-14);
  }
  // The first point: 0.1 m along the body's x, turned 30 degrees about z.
  EXPECT_NEAR(points.position(0, motion)[0], 0.5 + 0.1 * std::cos(std::numbers::pi / 6), 1e-15);
}

TEST(BodyPoints, LoadsSumPerBodyWithTheirMoments) {
  const BodyPoints points({{0, Vec3(0.1, 0, 0)}, {0, Vec3(-0.1, 0, 0)}, {1, Vec3::Zero()}});
  std::vector<BodyKinematics> motion(2);
  motion[1].position = Vec3(5, 0, 0);
  // A couple on body 0 (no net force), a push on body 1 through its centre.
  const std::vector<Vec3> force{Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(2, 0, 0)};
  const std::vector<Wrench> loads = points.loads(force, motion, 2);
  ASSERT_EQ(loads.size(), 2u);
  EXPECT_EQ(loads[0].force, Vec3::Zero());
  EXPECT_NEAR((loads[0].moment - Vec3(0, 0, 0.2)).norm(), 0, 1e-15);
  EXPECT_EQ(loads[1].force, Vec3(2, 0, 0));
  EXPECT_EQ(loads[1].moment, Vec3::Zero());
}

TEST(BodyPoints, FirstOfEachBodyGivesTheRunsOfPointsAndRefusesMixedOnes) {
  // Body 1 has no points: it starts and ends where body 2 starts.
  const BodyPoints points({{0, Vec3::Zero()}, {0, Vec3::Zero()}, {2, Vec3::Zero()}});
  EXPECT_EQ(points.first_of_each_body(4), (std::vector<std::uint32_t>{0, 2, 2, 3, 3}));
  const BodyPoints mixed({{0, Vec3::Zero()}, {1, Vec3::Zero()}, {0, Vec3::Zero()}});
  EXPECT_THROW(mixed.first_of_each_body(2), std::logic_error);
}

}  // namespace
}  // namespace sluice
