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

// Kleefsman's obstacle is 0.161 m long: 10.73 spacings of 0.015 m. Each face, upper ones too,
// must have its outer layer dx/2 behind it, and no two particles may come closer than dx, also in
// boxes too thin for two full sets of layers; a box under two spacings thick has one layer,
// centred.
TEST(Sampling, SolidBoxHasItsOuterLayerHalfASpacingBehindEveryFace) {
  const double dx = 0.015;
  for (const Vec3& size : {Vec3(0.161, 0.403, 0.161), Vec3(1.3 * dx, 2.7 * dx, 3.5 * dx)}) {
    const AxisBox solid = box(Vec3(0.6635, 0.2955, 0), Vec3(0.6635, 0.2955, 0) + size);
    const auto points = sample_solid_box<3>(solid, dx, 3);
    ASSERT_FALSE(points.empty());
    for (int a = 0; a < 3; ++a) {
      double nearest_min = 1e300, nearest_max = 1e300;
      for (const auto& p : points) {
        nearest_min = std::min(nearest_min, p[a] - solid.min[a]);
        nearest_max = std::min(nearest_max, solid.max[a] - p[a]);
      }
      const double expected = size[a] < 2 * dx ? 0.5 * size[a] : 0.5 * dx;
      EXPECT_NEAR(nearest_min, expected, 1e-12) << "axis " << a;
      EXPECT_NEAR(nearest_max, expected, 1e-12) << "axis " << a;
    }
    double closest = 1e300;
    for (std::size_t i = 0; i < points.size(); ++i) {
      for (std::size_t j = i + 1; j < points.size(); ++j) {
        closest = std::min(closest, (points[i] - points[j]).norm());
      }
    }
    EXPECT_GE(closest, dx - 1e-12);
  }
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
