#include "sluice/geometry/signed_distance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace sluice {
namespace {

void expect_point(const SurfacePoint& p, double distance, const Vec3& closest, const Vec3& normal) {
  EXPECT_NEAR(p.distance, distance, 1e-12);
  EXPECT_NEAR((p.closest - closest).norm(), 0, 1e-12) << p.closest.transpose();
  EXPECT_NEAR((p.normal - normal).norm(), 0, 1e-12) << p.normal.transpose();
}

TEST(SignedDistance, Box) {
  const Vec3 half(0.5, 0.2, 0.1);
  expect_point(box_surface(half, Vec3(1, 0, 0)), 0.5, Vec3(0.5, 0, 0), Vec3::UnitX());
  expect_point(box_surface(half, Vec3(0, 0, -0.05)), -0.05, Vec3(0, 0, -0.1), -Vec3::UnitZ());
  // Beyond an edge: the edge is nearest, along the diagonal.
  expect_point(box_surface(half, Vec3(0.8, 0.6, 0)), 0.5, Vec3(0.5, 0.2, 0), Vec3(0.6, 0.8, 0));
  // Infinite along y (a 2D section).
  const Vec3 slab(0.5, std::numeric_limits<double>::infinity(), 0.1);
  expect_point(box_surface(slab, Vec3(0, 3, 0.3)), 0.2, Vec3(0, 3, 0.1), Vec3::UnitZ());
}

TEST(SignedDistance, SphereCylinderAndPlane) {
  expect_point(sphere_surface(0.1, Vec3(0, 0.3, 0.4)), 0.4, Vec3(0, 0.06, 0.08), Vec3(0, 0.6, 0.8));
  expect_point(sphere_surface(0.1, Vec3(0.05, 0, 0)), -0.05, Vec3(0.1, 0, 0), Vec3::UnitX());
  // Side, cap and rim of a cylinder of radius 0.1 and length 0.4.
  expect_point(cylinder_surface(0.1, 0.2, Vec3(0.3, 0, 0.1)), 0.2, Vec3(0.1, 0, 0.1),
               Vec3::UnitX());
  expect_point(cylinder_surface(0.1, 0.2, Vec3(0, 0.05, -0.5)), 0.3, Vec3(0, 0.05, -0.2),
               -Vec3::UnitZ());
  expect_point(cylinder_surface(0.1, 0.2, Vec3(0.4, 0, 0.6)), 0.5, Vec3(0.1, 0, 0.2),
               Vec3(0.6, 0, 0.8));
  expect_point(cylinder_surface(0.1, 0.2, Vec3(0.09, 0, 0)), -0.01, Vec3(0.1, 0, 0), Vec3::UnitX());
  expect_point(cylinder_surface(0.1, 0.2, Vec3(0, 0, 0.19)), -0.01, Vec3(0, 0, 0.2), Vec3::UnitZ());
  const Vec3 n = Vec3(1, 0, 1).normalized();
  expect_point(plane_surface(Vec3::Zero(), n, Vec3(1, 2, 1)), std::sqrt(2.0), Vec3(0, 2, 0), n);
}

// The gradient of the distance is the normal, and the closest point lies at the distance, for
// random points around each shape.
TEST(SignedDistance, ConsistentEverywhere) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-0.5, 0.5);
  const double h = 1e-7;
  for (int k = 0; k < 500; ++k) {
    const Vec3 x(unit(random), unit(random), unit(random));
    for (int shape = 0; shape < 3; ++shape) {
      auto query = [&](const Vec3& y) {
        return shape == 0   ? box_surface(Vec3(0.2, 0.15, 0.1), y)
               : shape == 1 ? sphere_surface(0.2, y)
                            : cylinder_surface(0.15, 0.2, y);
      };
      const SurfacePoint p = query(x);
      EXPECT_NEAR((x - p.closest).norm(), std::abs(p.distance), 1e-12);
      EXPECT_NEAR(p.normal.norm(), 1, 1e-12);
      Vec3 gradient;
      for (int a = 0; a < 3; ++a) {
        Vec3 step = Vec3::Zero();
        step[a] = h;
        gradient[a] = (query(x + step).distance - query(x - step).distance) / (2 * h);
      }
      // Where two faces are equally near the gradient jumps; skip those points.
      if (std::abs(gradient.norm() - 1) < 1e-5) {
        EXPECT_NEAR((gradient - p.normal).norm(), 0, 1e-5) << shape << " " << x.transpose();
      }
    }
  }
}

TEST(SignedDistance, SampledSurfaceIsTheNearestFacePlane) {
  const std::vector<Vec3> position{Vec3(0, 0, 0.1), Vec3(0.1, 0, 0)};
  const std::vector<Vec3> normal{Vec3::UnitZ(), Vec3::UnitX()};
  expect_point(sampled_surface(position, normal, Vec3(0.01, 0.02, 0.3)), 0.2, Vec3(0.01, 0.02, 0.1),
               Vec3::UnitZ());
  expect_point(sampled_surface(position, normal, Vec3(0.08, 0, 0.01)), -0.02, Vec3(0.1, 0, 0.01),
               Vec3::UnitX());
}

}  // namespace
}  // namespace sluice
