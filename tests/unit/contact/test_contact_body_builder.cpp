// Contact bodies built from shapes: tank walls face into the tank and cover its closed sides.
#include <gtest/gtest.h>

#include "sluice/contact/contact_body_builder.hpp"

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

}  // namespace
}  // namespace sluice
