// Mass, centre of mass and inertia of analytic shapes and of triangle meshes.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sluice/rigid/mass_properties.hpp"

namespace sluice {
namespace {

constexpr double kPi = std::numbers::pi;

// Largest absolute entry difference, relative to the largest entry of `expected`.
double relative_difference(const Eigen::Matrix3d& actual, const Eigen::Matrix3d& expected) {
  return (actual - expected).cwiseAbs().maxCoeff() / expected.cwiseAbs().maxCoeff();
}

// Box with corners at +-size/2, 12 outward-wound triangles.
TriangleMesh box_mesh(const Vec3& size) {
  TriangleMesh m;
  for (int k = 0; k < 8; ++k) {
    m.vertices.emplace_back((k & 1 ? 0.5 : -0.5) * size.x(), (k & 2 ? 0.5 : -0.5) * size.y(),
                            (k & 4 ? 0.5 : -0.5) * size.z());
  }
  // Each face as a quad (a, b, c, d), counter-clockwise seen from outside.
  const std::uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                     {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  return m;
}

// Sphere of radius r with vertices on it: `rings` latitude bands, `sectors` longitudes.
TriangleMesh uv_sphere(double r, int rings, int sectors) {
  TriangleMesh m;
  m.vertices.emplace_back(0, 0, r);  // north pole: 0
  for (int i = 1; i < rings; ++i) {
    const double theta = kPi * i / rings;
    for (int j = 0; j < sectors; ++j) {
      const double phi = 2 * kPi * j / sectors;
      m.vertices.emplace_back(r * std::sin(theta) * std::cos(phi),
                              r * std::sin(theta) * std::sin(phi), r * std::cos(theta));
    }
  }
  const auto south = static_cast<std::uint32_t>(m.vertices.size());
  m.vertices.emplace_back(0, 0, -r);
  auto at = [sectors](int ring, int j) {  // ring 1 .. rings-1
    return static_cast<std::uint32_t>(1 + (ring - 1) * sectors + (j % sectors));
  };
  for (int j = 0; j < sectors; ++j) {
    m.triangles.push_back({0, at(1, j), at(1, j + 1)});
    m.triangles.push_back({south, at(rings - 1, j + 1), at(rings - 1, j)});
    for (int i = 1; i < rings - 1; ++i) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return m;
}

// Prism over the regular n-gon inscribed in the circle of radius r, axis z, from -h/2 to h/2.
TriangleMesh ngon_prism(double r, double h, int n) {
  TriangleMesh m;
  for (int j = 0; j < n; ++j) {
    const double phi = 2 * kPi * j / n;
    m.vertices.emplace_back(r * std::cos(phi), r * std::sin(phi), -h / 2);
    m.vertices.emplace_back(r * std::cos(phi), r * std::sin(phi), h / 2);
  }
  const auto bottom = static_cast<std::uint32_t>(m.vertices.size());
  m.vertices.emplace_back(0, 0, -h / 2);
  m.vertices.emplace_back(0, 0, h / 2);
  const std::uint32_t top = bottom + 1;
  for (int j = 0; j < n; ++j) {
    const auto b0 = static_cast<std::uint32_t>(2 * j);
    const auto b1 = static_cast<std::uint32_t>(2 * ((j + 1) % n));
    m.triangles.push_back({b0, b1, b1 + 1});  // side
    m.triangles.push_back({b0, b1 + 1, b0 + 1});
    m.triangles.push_back({bottom, b1, b0});
    m.triangles.push_back({top, b0 + 1, b1 + 1});
  }
  return m;
}

TEST(MassProperties, BoxMatchesTextbook) {
  const Vec3 size(1.0, 2.0, 3.0);
  const double density = 500.0;
  const auto p = box_mass_properties(size, density);
  const double m = density * 6.0;
  EXPECT_DOUBLE_EQ(p.mass, m);
  EXPECT_EQ(p.center_of_mass, Vec3::Zero());
  EXPECT_DOUBLE_EQ(p.inertia(0, 0), m * (4.0 + 9.0) / 12);  // m (b^2 + c^2) / 12
  EXPECT_DOUBLE_EQ(p.inertia(1, 1), m * (1.0 + 9.0) / 12);
  EXPECT_DOUBLE_EQ(p.inertia(2, 2), m * (1.0 + 4.0) / 12);
  EXPECT_TRUE(p.inertia.isDiagonal());
}

TEST(MassProperties, SphereMatchesTextbook) {
  const double r = 0.3;
  const double density = 1000.0;
  const auto p = sphere_mass_properties(r, density);
  const double m = density * 4.0 / 3.0 * kPi * r * r * r;
  EXPECT_DOUBLE_EQ(p.mass, m);
  for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(p.inertia(i, i), 0.4 * m * r * r);  // 2/5 m r^2
  EXPECT_TRUE(p.inertia.isDiagonal());
}

TEST(MassProperties, CylinderMatchesTextbook) {
  const double r = 0.5;
  const double h = 2.0;
  const double density = 800.0;
  const auto p = cylinder_mass_properties(r, h, density);
  const double m = density * kPi * r * r * h;
  EXPECT_DOUBLE_EQ(p.mass, m);
  EXPECT_DOUBLE_EQ(p.inertia(0, 0), m * (3 * r * r + h * h) / 12);  // m (3 r^2 + h^2) / 12
  EXPECT_DOUBLE_EQ(p.inertia(1, 1), m * (3 * r * r + h * h) / 12);
  EXPECT_DOUBLE_EQ(p.inertia(2, 2), m * r * r / 2);  // m r^2 / 2
  EXPECT_TRUE(p.inertia.isDiagonal());
}

TEST(MassProperties, AnalyticShapesRejectBadSizes) {
  EXPECT_THROW(box_mass_properties(Vec3(1, 0, 1), 1.0), std::invalid_argument);
  EXPECT_THROW(box_mass_properties(Vec3(1, 1, 1), -1.0), std::invalid_argument);
  EXPECT_THROW(sphere_mass_properties(std::nan(""), 1.0), std::invalid_argument);
  EXPECT_THROW(cylinder_mass_properties(1.0, -2.0, 1.0), std::invalid_argument);
}

// A box is a polyhedron: the mesh integrals are exact, up to rounding.
TEST(MassProperties, MeshCubeIsExact) {
  const Vec3 size(1.0, 2.0, 3.0);
  const auto mesh = box_mesh(size);
  ASSERT_EQ(mesh.triangles.size(), 12u);
  const auto p = mesh_mass_properties(mesh, 500.0);
  const auto expected = box_mass_properties(size, 500.0);
  EXPECT_NEAR(p.mass, expected.mass, 1e-12 * expected.mass);
  EXPECT_LT(p.center_of_mass.norm(), 1e-14);
  EXPECT_LT(relative_difference(p.inertia, expected.inertia), 1e-13);
}

// The inscribed regular n-gon prism has closed-form area A = n r^2 sin(a) / 2 and polar moment
// J = n r^4 sin(a) (2 + cos(a)) / 12, a = 2 pi / n: the mesh must match those to rounding, and
// approach the cylinder as the prism fills it.
TEST(MassProperties, MeshPrismMatchesClosedFormAndApproachesCylinder) {
  const double r = 0.5;
  const double h = 2.0;
  const double density = 800.0;
  const int n = 256;
  const auto p = mesh_mass_properties(ngon_prism(r, h, n), density);

  const double a = 2 * kPi / n;
  const double area = n * r * r * std::sin(a) / 2;
  const double polar = n * r * r * r * r * std::sin(a) * (2 + std::cos(a)) / 12;
  const double m = density * area * h;
  // I_zz = rho h J; I_xx = I_yy = rho (h J / 2 + A h^3 / 12) (n-fold symmetry: int x^2 = J / 2).
  const Eigen::Matrix3d prism =
      Vec3(density * (h * polar / 2 + area * h * h * h / 12),
           density * (h * polar / 2 + area * h * h * h / 12), density * h * polar)
          .asDiagonal();
  EXPECT_NEAR(p.mass, m, 1e-12 * m);
  EXPECT_LT(p.center_of_mass.norm(), 1e-13);
  EXPECT_LT(relative_difference(p.inertia, prism), 1e-12);

  // The prism lies between the cylinders of radius r cos(pi / n) and r; mass and inertia grow
  // with the region (non-negative integrands), so they lie between the two cylinders' values.
  const auto outer = cylinder_mass_properties(r, h, density);
  const auto inner = cylinder_mass_properties(r * std::cos(kPi / n), h, density);
  EXPECT_GT(p.mass, inner.mass);
  EXPECT_LT(p.mass, outer.mass);
  for (int i = 0; i < 3; ++i) {
    EXPECT_GT(p.inertia(i, i), inner.inertia(i, i));
    EXPECT_LT(p.inertia(i, i), outer.inertia(i, i));
  }
  // For n = 256 that bracket is 1 - cos^4(pi / 256) ~ 3e-4 wide in relative terms.
  EXPECT_NEAR(p.mass, outer.mass, 3.1e-4 * outer.mass);
  EXPECT_LT(relative_difference(p.inertia, outer.inertia), 3.1e-4);
}

// The inscribed UV sphere is convex with every face plane at least r_in from the centre, so it
// contains the ball of radius r_in and lies inside the ball of radius r: mass and moments are
// bracketed by the two balls' values (r_in is measured on the mesh itself).
TEST(MassProperties, MeshSphereIsBracketedByInscribedAndCircumscribedBalls) {
  const double r = 0.3;
  const double density = 1000.0;
  const auto mesh = uv_sphere(r, 64, 128);
  double r_in = r;
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.vertices[t[0]];
    const Vec3 normal = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).normalized();
    ASSERT_GT(normal.dot(a), 0.0);  // outward
    r_in = std::min(r_in, normal.dot(a));
  }
  const auto p = mesh_mass_properties(mesh, density);
  const auto outer = sphere_mass_properties(r, density);
  const auto inner = sphere_mass_properties(r_in, density);
  EXPECT_GT(p.mass, inner.mass);
  EXPECT_LT(p.mass, outer.mass);
  for (int i = 0; i < 3; ++i) {
    EXPECT_GT(p.inertia(i, i), inner.inertia(i, i));
    EXPECT_LT(p.inertia(i, i), outer.inertia(i, i));
  }
  // Symmetric about every coordinate plane: centre at the origin, no products of inertia.
  EXPECT_LT(p.center_of_mass.norm(), 1e-14);
  EXPECT_LT(std::abs(p.inertia(0, 1)) + std::abs(p.inertia(0, 2)) + std::abs(p.inertia(1, 2)),
            1e-12 * p.inertia(0, 0));
  // With 64 x 128 bands r_in / r ~ cos(pi / 64) ~ 0.9988, so the bracket is under 1%
  // (1 - 0.9988^5 ~ 0.6% for the moments).
  EXPECT_NEAR(p.mass, outer.mass, 0.01 * outer.mass);
  EXPECT_LT(relative_difference(p.inertia, outer.inertia), 0.01);
}

TEST(MassProperties, MovedMeshBoxHasTranslatedCentreAndRotatedInertia) {
  const Vec3 size(1.0, 2.0, 3.0);
  const Eigen::Matrix3d rot =
      Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  const Vec3 shift(100.0, -50.0, 30.0);
  auto mesh = box_mesh(size);
  for (Vec3& v : mesh.vertices) v = rot * v + shift;

  const auto p = mesh_mass_properties(mesh, 500.0);
  const auto body = box_mass_properties(size, 500.0);
  const Eigen::Matrix3d expected = rot * body.inertia * rot.transpose();
  EXPECT_NEAR(p.mass, body.mass, 1e-12 * body.mass);
  EXPECT_LT((p.center_of_mass - shift).norm(), 1e-12 * shift.norm());
  EXPECT_LT(relative_difference(p.inertia, expected), 1e-12);
  EXPECT_TRUE(p.inertia.isApprox(p.inertia.transpose(), 1e-15));
  // The box's axes are no longer the frame's: products of inertia appear.
  EXPECT_GT(std::abs(p.inertia(0, 1)), 0.01 * p.inertia(0, 0));
  EXPECT_GT(std::abs(p.inertia(0, 2)), 0.01 * p.inertia(0, 0));
  EXPECT_GT(std::abs(p.inertia(1, 2)), 0.01 * p.inertia(0, 0));
}

TEST(MassProperties, MeshRejectsInsideOutOrEmptyMeshes) {
  auto mesh = box_mesh(Vec3(1, 1, 1));
  for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  EXPECT_THROW(mesh_mass_properties(mesh, 1.0), std::invalid_argument);
  EXPECT_THROW(mesh_mass_properties(TriangleMesh{}, 1.0), std::invalid_argument);
  EXPECT_THROW(mesh_mass_properties(box_mesh(Vec3(1, 1, 1)), 0.0), std::invalid_argument);
}

TEST(MassProperties, WithMassScalesInertiaAndKeepsCentre) {
  auto p = box_mass_properties(Vec3(1.0, 2.0, 3.0), 500.0);
  p.center_of_mass = Vec3(0.1, 0.2, 0.3);
  const auto q = with_mass(p, 42.0);
  EXPECT_DOUBLE_EQ(q.mass, 42.0);
  EXPECT_EQ(q.center_of_mass, p.center_of_mass);
  EXPECT_TRUE(q.inertia.isApprox(p.inertia * (42.0 / p.mass), 1e-15));
  // Same as a box of the matching density.
  EXPECT_TRUE(q.inertia.isApprox(box_mass_properties(Vec3(1.0, 2.0, 3.0), 7.0).inertia, 1e-14));
  EXPECT_THROW(with_mass(p, 0.0), std::invalid_argument);
  EXPECT_THROW(with_mass(MassProperties{}, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace sluice
