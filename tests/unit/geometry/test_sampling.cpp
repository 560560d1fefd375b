// Particle sampling of shapes: counts and placement of fluid lattices and boundary layers.
#include <gtest/gtest.h>

#include "sluice/geometry/sampling.hpp"

namespace sluice {
namespace {

AxisBox box(Vec3 min, Vec3 max) {
  return AxisBox{min, max};
}

TEST(Sampling, BoxVolumeIsALatticeOfWholeParticles) {
  const auto points = sample_box_volume<3>(box(Vec3(0, 0, 0), Vec3(1.0, 0.5, 0.3)), 0.1);
  EXPECT_EQ(points.size(), 10u * 5u * 3u);
  for (const auto& p : points) {
    EXPECT_GE(p.minCoeff(), 0.05 - 1e-12);
    EXPECT_LE(p[0], 0.95 + 1e-12);
  }
  // 2D lives in the x-z plane: the y extent of the box is ignored.
  EXPECT_EQ(sample_box_volume<2>(box(Vec3(0, 0, 0), Vec3(1.0, 0, 0.3)), 0.1).size(), 30u);
}

TEST(Sampling, OpenTopTankHasLayersBehindClosedSidesOnly) {
  const double dx = 0.1;
  const int layers = 3;
  const auto walls = sample_tank_walls<2>(box(Vec3(0, 0, 0), Vec3(1, 0, 1)), {"z+"}, dx, layers);
  // Floor: (10 + 2 * 3) x 3; two side walls: 3 x 10 each (corners counted with the floor).
  EXPECT_EQ(walls.size(), 16u * 3u + 2u * 3u * 10u);
  for (const auto& p : walls) {
    const bool behind_floor = p[1] < 0;
    const bool behind_side = p[0] < 0 || p[0] > 1;
    EXPECT_TRUE(behind_floor || behind_side) << p.transpose();
    EXPECT_LT(p[1], 1.0) << "nothing above an open top";
    EXPECT_GT(p[1], -layers * dx);
  }
}

TEST(Sampling, SolidBoxKeepsOnlyTheLayersUnderItsSurface) {
  const double dx = 0.1;
  const auto points = sample_solid_box<3>(box(Vec3(0, 0, 0), Vec3(1, 1, 1)), dx, 2);
  EXPECT_EQ(points.size(), 1000u - 6u * 6u * 6u);  // a 10^3 lattice less its 6^3 core
}

TEST(Sampling, PlaneLayersLieBehindThePlane) {
  const double dx = 0.05;
  const Vec3 point(0, 0, 0.2), normal = Vec3(0.3, 0, 1).normalized();
  const auto points =
      sample_plane_layers<2>(point, normal, box(Vec3(0, 0, 0), Vec3(1, 0, 1)), dx, 3);
  ASSERT_FALSE(points.empty());
  for (const auto& p : points) {
    const double s = (to_3d<2>(p) - point).dot(normal);
    EXPECT_LT(s, 0);
    EXPECT_GT(s, -3 * dx);
  }
}

}  // namespace
}  // namespace sluice
