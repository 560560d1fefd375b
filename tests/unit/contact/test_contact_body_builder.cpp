// Contact bodies built from shapes: tank walls face into the tank and cover its closed sides;
// a plane wall tiles its part inside the domain and puts bodies in reach only near its plane.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sluice/contact/contact_body_builder.hpp"
#include "sluice/contact/multibody_system.hpp"

namespace sluice {
namespace {

TEST(TankWalls, OneFixedBodyPerClosedSideFacingIn) {
  const Vec3 lo(0, 0, 0), hi(1.0, 0.5, 0.4);
  const ContactMaterial material;
  const auto walls = make_tank_walls(lo, hi, {"z+"}, 0.05, material);
  ASSERT_EQ(walls.size(), 5u);  // the open top has no wall
  double area = 0;
  for (const auto& wall : walls) {
    EXPECT_TRUE(wall.fixed);
    ASSERT_FALSE(wall.surface_position.empty());
    const Vec3 n = wall.surface_normal.front();
    for (std::size_t k = 0; k < wall.surface_position.size(); ++k) {
      const Vec3& p = wall.surface_position[k];
      EXPECT_EQ(wall.surface_normal[k], n) << "one side, one normal";
      EXPECT_TRUE(((p.array() >= lo.array() - 1e-12) && (p.array() <= hi.array() + 1e-12)).all());
      // Facing in: a step along the normal stays inside the tank.
      const Vec3 q = p + 0.01 * n;
      EXPECT_TRUE(((q.array() > lo.array()) && (q.array() < hi.array())).all()) << p.transpose();
      area += wall.surface_area[k];
    }
  }
  // Floor plus four sides of the open-top tank.
  EXPECT_NEAR(area, 1.0 * 0.5 + 2 * (1.0 * 0.4) + 2 * (0.5 * 0.4), 1e-12);
}

TEST(FloorPatch, CoversItsSquareFacingUp) {
  const ContactBody floor = make_floor_patch(0.5, 0.1, ContactMaterial{});
  EXPECT_EQ(floor.surface_position.size(), 100u);
  double area = 0;
  for (std::size_t k = 0; k < floor.surface_position.size(); ++k) {
    EXPECT_EQ(floor.surface_normal[k], Vec3::UnitZ());
    area += floor.surface_area[k];
  }
  EXPECT_NEAR(area, 1.0, 1e-12);
}

TEST(PlaneWall, TilesItsSectionOfTheBox) {
  const Vec3 lo(0, 0, 0), hi(1.0, 0.5, 1.0);
  const ContactBody wall =
      make_plane_wall(Vec3(0, 0, 0.1), Vec3::UnitZ(), lo, hi, 0.1, ContactMaterial{}, 3);
  EXPECT_TRUE(wall.fixed);
  ASSERT_TRUE(wall.half_space.has_value());
  EXPECT_EQ(wall.surface_position.size(), 50u);
  double area = 0;
  for (std::size_t k = 0; k < wall.surface_position.size(); ++k) {
    const Vec3& p = wall.surface_position[k];
    EXPECT_DOUBLE_EQ(p[2], 0.1);
    EXPECT_TRUE(((p.array() >= lo.array()) && (p.array() <= hi.array())).all()) << p.transpose();
    EXPECT_EQ(wall.surface_normal[k], Vec3::UnitZ());
    area += wall.surface_area[k];
  }
  EXPECT_NEAR(area, 0.5, 1e-12);
}

TEST(PlaneWall, SlopeIn2DIsItsChordThroughTheDomain) {
  const double angle = std::numbers::pi / 6, dx = 0.01;
  const Vec3 normal(std::sin(angle), 0, std::cos(angle));
  const ContactBody wall = make_plane_wall(Vec3::Zero(), normal, Vec3(-1, -1, -1), Vec3(1, 1, 1),
                                           dx, ContactMaterial{}, 2);
  double length = 0;
  for (std::size_t k = 0; k < wall.surface_position.size(); ++k) {
    const Vec3& p = wall.surface_position[k];
    EXPECT_NEAR(p.dot(normal), 0, 1e-12);
    EXPECT_EQ(p[1], 0);
    length += wall.surface_area[k];
  }
  // The line z = -x tan 30 crosses the square [-1, 1]^2 from x = -1 to x = 1.
  EXPECT_NEAR(length, 2 / std::cos(angle), dx);
}

TEST(PlaneWall, OnlyABodyNearTheSlopeIsInReach) {
  // A ball high above a 30-degree slope lies inside the slope's bounding box but far from its
  // plane: no contact is in reach, so the solid takes the whole step. On the slope, it does not.
  const double angle = std::numbers::pi / 6, dx = 0.01, radius = 0.05, dt = 1e-3;
  const Vec3 normal(std::sin(angle), 0, std::cos(angle));
  const ContactMaterial material{1e9, 0.3, 0.5, 0.5};
  auto solid_step_with_ball_at = [&](double height) {
    MultibodySystem system(dx, Vec3(0, 0, -9.81));
    ContactBody ball =
        make_contact_body(sample_sphere_body(radius, dx, 0, 3),
                          sphere_mass_properties(radius, 1000.0), material, radius, false);
    ball.spherical = true;
    ball.state.position = (radius + height) * normal;
    system.add(std::move(ball));
    system.add(make_plane_wall(Vec3::Zero(), normal, Vec3(-1, -0.2, -1), Vec3(1, 0.2, 1), dx,
                               material, 3));
    return system.solid_step(dt);
  };
  EXPECT_EQ(solid_step_with_ball_at(0.5), dt);
  EXPECT_LT(solid_step_with_ball_at(0.0), 0.1 * dt);
}

}  // namespace
}  // namespace sluice
