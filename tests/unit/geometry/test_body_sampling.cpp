// Body particles of rigid bodies: surface particles on the faces with their face's outward normal
// and an area share that tiles the surface exactly, plus interior layers at the right depths.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "sluice/geometry/body_sampling.hpp"

namespace sluice {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Arrays of equal length, surface particles first, interior ones with zero normal and area.
void expect_well_formed(const BodySample& s) {
  ASSERT_EQ(s.normal.size(), s.position.size());
  ASSERT_EQ(s.area.size(), s.position.size());
  ASSERT_EQ(s.layer.size(), s.position.size());
  const std::size_t ns = s.surface_count();
  for (std::size_t i = 0; i < s.position.size(); ++i) {
    ASSERT_TRUE(s.position[i].allFinite());
    if (i < ns) {
      ASSERT_EQ(s.layer[i], 0);
      EXPECT_NEAR(s.normal[i].norm(), 1.0, 1e-12);
      EXPECT_GT(s.area[i], 0.0);
    } else {
      ASSERT_GE(s.layer[i], 1);
      ASSERT_GE(s.layer[i], s.layer[i - 1]);  // grouped by layer
      EXPECT_EQ(s.normal[i], Vec3::Zero());
      EXPECT_EQ(s.area[i], 0.0);
    }
  }
}

double total_area(const BodySample& s) {
  double sum = 0;
  for (std::size_t i = 0; i < s.surface_count(); ++i) sum += s.area[i];
  return sum;
}

Vec3 total_area_vector(const BodySample& s) {
  Vec3 sum = Vec3::Zero();
  for (std::size_t i = 0; i < s.surface_count(); ++i) sum += s.area[i] * s.normal[i];
  return sum;
}

// Smallest and largest nearest-neighbour distance among the surface particles.
std::pair<double, double> nearest_neighbour_range(const BodySample& s) {
  const std::size_t n = s.surface_count();
  double lo = 1e300, hi = 0;
  for (std::size_t i = 0; i < n; ++i) {
    double best = 1e300;
    for (std::size_t j = 0; j < n; ++j) {
      if (j != i) best = std::min(best, (s.position[i] - s.position[j]).norm());
    }
    lo = std::min(lo, best);
    hi = std::max(hi, best);
  }
  return {lo, hi};
}

void expect_spacing_about(const BodySample& s, double dx) {
  const auto [lo, hi] = nearest_neighbour_range(s);
  EXPECT_GE(lo, 0.5 * dx);
  EXPECT_LE(hi, 1.5 * dx);
}

int count_layer(const BodySample& s, int layer) {
  return static_cast<int>(std::count(s.layer.begin(), s.layer.end(), layer));
}

// Depth of a point inside the box of edge lengths `size` centred at the origin (axes given).
double box_depth(const Vec3& p, const Vec3& size, const std::vector<int>& axes) {
  double d = 1e300;
  for (int a : axes) d = std::min(d, 0.5 * size[a] - std::abs(p[a]));
  return d;
}

// ---------------------------------------------------------------------------------------------
// Boxes

TEST(BodySampling, BoxSurfaceTilesEachFaceWithItsOwnNormal) {
  const Vec3 size(1.0, 0.6, 0.4);
  const double dx = 0.1;
  const BodySample s = sample_box_body(size, dx, 2, 3);
  expect_well_formed(s);
  ASSERT_EQ(s.surface_count(), 2u * (6 * 4 + 10 * 4 + 10 * 6));
  const double area = 2 * (1.0 * 0.6 + 1.0 * 0.4 + 0.6 * 0.4);
  EXPECT_NEAR(total_area(s), area, 1e-12);
  EXPECT_LE(total_area_vector(s).norm(), 1e-9 * area);

  std::array<std::array<int, 2>, 3> count{};
  for (std::size_t i = 0; i < s.surface_count(); ++i) {
    const Vec3& p = s.position[i];
    const Vec3& n = s.normal[i];
    int axis = -1;
    for (int a = 0; a < 3; ++a) {
      if (std::abs(n[a]) == 1.0) axis = a;
    }
    ASSERT_GE(axis, 0) << "normal must be a face normal: " << n.transpose();
    ++count[axis][n[axis] > 0];
    EXPECT_EQ(p[axis], 0.5 * n[axis] * size[axis]);  // on its own face
    for (int b = 0; b < 3; ++b) {
      if (b != axis) {
        EXPECT_LT(std::abs(p[b]), 0.5 * size[b]);  // not on an edge
      }
    }
    EXPECT_GT(p.dot(n), 0.0);
  }
  const std::array<int, 3> per_face = {6 * 4, 10 * 4, 10 * 6};  // n_y n_z, n_x n_z, n_x n_y
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(count[a][0], per_face[a]);
    EXPECT_EQ(count[a][1], per_face[a]);
  }
  for (std::size_t i = 0; i < s.surface_count(); ++i) {
    if (s.normal[i] == Vec3(1, 0, 0)) {
      EXPECT_NEAR(s.area[i], (0.6 / 6) * (0.4 / 4), 1e-15);
    }
  }
  expect_spacing_about(s, dx);
}

TEST(BodySampling, BoxInteriorLayersAreShellsAtDepthsOfWholeSpacings) {
  const Vec3 size(1.0, 0.6, 0.4);
  const double dx = 0.1;
  const BodySample s = sample_box_body(size, dx, 3, 3);
  expect_well_formed(s);
  // Layer 1: the surface of the 0.8 x 0.4 x 0.2 box. Layer 2: 0.6 x 0.2 x 0 is flat, one sheet
  // of 6 x 2 at z = 0. Layer 3 does not fit.
  EXPECT_EQ(count_layer(s, 1), 2 * (4 * 2 + 8 * 2 + 8 * 4));
  EXPECT_EQ(count_layer(s, 2), 6 * 2);
  EXPECT_EQ(count_layer(s, 3), 0);
  for (std::size_t i = s.surface_count(); i < s.position.size(); ++i) {
    EXPECT_NEAR(box_depth(s.position[i], size, {0, 1, 2}), s.layer[i] * dx, 1e-12);
  }
}

TEST(BodySampling, ThinBoxInteriorCollapsesOntoTheMidPlane) {
  const double dx = 0.1;
  for (double thickness : {0.24, 0.19, 0.16, 0.14, 0.12, 0.3, 0.41, 0.44}) {
    const Vec3 size(1.0, 0.7, thickness);
    const BodySample s = sample_box_body(size, dx, 4, 3);
    expect_well_formed(s);
    EXPECT_NEAR(total_area(s), 2 * (0.7 + thickness * 1.7), 1e-12);
    for (std::size_t i = s.surface_count(); i < s.position.size(); ++i) {
      const double depth = box_depth(s.position[i], size, {0, 1, 2});
      EXPECT_GT(depth, 0.0);
      EXPECT_GE(depth, s.layer[i] * dx - 0.25 * dx - 1e-12) << thickness;
      EXPECT_LE(depth, s.layer[i] * dx + 0.25 * dx + 1e-12) << thickness;
    }
  }
  // 0.24 thick: layer 1 is one sheet of the 0.8 x 0.5 cells at z = 0, nothing deeper.
  const BodySample s = sample_box_body(Vec3(1.0, 0.7, 0.24), dx, 4, 3);
  EXPECT_EQ(count_layer(s, 1), 8 * 5);
  EXPECT_EQ(count_layer(s, 2), 0);
  for (std::size_t i = s.surface_count(); i < s.position.size(); ++i) {
    EXPECT_EQ(s.position[i][2], 0.0);
  }
  // 0.16 thick: a sheet at z = 0 as well; 0.14 thick: the faces are 1.4 dx apart, no layer.
  EXPECT_EQ(count_layer(sample_box_body(Vec3(1.0, 0.7, 0.16), dx, 4, 3), 1), 8 * 5);
  const BodySample none = sample_box_body(Vec3(1.0, 0.7, 0.14), dx, 4, 3);
  EXPECT_EQ(none.surface_count(), none.position.size());
}

TEST(BodySampling, BoxWithSidesNotMultiplesOfDxStillTilesExactly) {
  const Vec3 size(1.03, 0.57, 0.41);
  const double dx = 0.1;
  const BodySample s = sample_box_body(size, dx, 2, 3);
  expect_well_formed(s);
  EXPECT_EQ(s.surface_count(), 2u * (6 * 4 + 10 * 4 + 10 * 6));  // round(10.3), round(5.7), ...
  const double area = 2 * (1.03 * 0.57 + 1.03 * 0.41 + 0.57 * 0.41);
  EXPECT_NEAR(total_area(s), area, 1e-12);
  EXPECT_LE(total_area_vector(s).norm(), 1e-9 * area);
  expect_spacing_about(s, dx);
  // Layer 1 is the surface of the 0.83 x 0.37 x 0.21 box; layer 2 (0.63 x 0.17 x 0.01) is the
  // sheet z = 0, 0.205 deep.
  EXPECT_EQ(count_layer(s, 2), 6 * 2);
  for (std::size_t i = s.surface_count(); i < s.position.size(); ++i) {
    EXPECT_NEAR(box_depth(s.position[i], size, {0, 1, 2}), s.layer[i] == 1 ? 0.1 : 0.205, 1e-12);
  }
  // A box smaller than dx gets one particle per face.
  const BodySample tiny = sample_box_body(Vec3(0.04, 0.03, 0.02), dx, 3, 3);
  EXPECT_EQ(tiny.position.size(), 6u);
  EXPECT_NEAR(total_area(tiny), 2 * (0.04 * 0.03 + 0.04 * 0.02 + 0.03 * 0.02), 1e-15);
}

TEST(BodySampling, Box2DIsTheRectangleInTheXzPlane) {
  const Vec3 size(1.0, 123.0, 0.4);  // y ignored
  const double dx = 0.1;
  const BodySample s = sample_box_body(size, dx, 1, 2);
  expect_well_formed(s);
  ASSERT_EQ(s.surface_count(), 2u * (4 + 10));
  EXPECT_NEAR(total_area(s), 2 * (1.0 + 0.4), 1e-12);
  EXPECT_LE(total_area_vector(s).norm(), 1e-12);
  int plus_x = 0;
  for (std::size_t i = 0; i < s.position.size(); ++i) {
    EXPECT_EQ(s.position[i][1], 0.0);
    EXPECT_EQ(s.normal[i][1], 0.0);
    if (s.layer[i] > 0) {
      EXPECT_NEAR(box_depth(s.position[i], size, {0, 2}), s.layer[i] * dx, 1e-12);
      continue;
    }
    const int axis = std::abs(s.normal[i][0]) == 1.0 ? 0 : 2;
    EXPECT_EQ(std::abs(s.normal[i][axis]), 1.0);
    EXPECT_EQ(s.position[i][axis], 0.5 * s.normal[i][axis] * size[axis]);
    EXPECT_LT(std::abs(s.position[i][2 - axis]), 0.5 * size[2 - axis]);
    EXPECT_GT(s.position[i].dot(s.normal[i]), 0.0);
    if (s.normal[i] == Vec3(1, 0, 0)) {
      ++plus_x;
      EXPECT_NEAR(s.area[i], 0.1, 1e-15);
    }
  }
  EXPECT_EQ(plus_x, 4);
  EXPECT_EQ(count_layer(s, 1), 2 * (2 + 8));  // the 0.8 x 0.2 rectangle
  expect_spacing_about(s, dx);
}

// ---------------------------------------------------------------------------------------------
// Spheres and circles

TEST(BodySampling, SphereSurfaceIsAClosedGoldenSpiral) {
  const double r = 0.5, dx = 0.05;
  const BodySample s = sample_sphere_body(r, dx, 3, 3);
  expect_well_formed(s);
  const double area = 4 * kPi * r * r;
  ASSERT_EQ(s.surface_count(), static_cast<std::size_t>(std::lround(area / (dx * dx))));
  EXPECT_NEAR(total_area(s), area, 1e-9 * area);
  EXPECT_LE(total_area_vector(s).norm(), 1e-9 * area);
  const double mean = area / s.surface_count();
  for (std::size_t i = 0; i < s.surface_count(); ++i) {
    EXPECT_NEAR(s.position[i].norm(), r, 1e-12);
    EXPECT_LE((s.normal[i] - s.position[i] / r).norm(), 1e-12);
    EXPECT_GT(s.position[i].dot(s.normal[i]), 0.0);
    EXPECT_NEAR(s.area[i], mean, 0.1 * mean);
  }
  expect_spacing_about(s, dx);
  for (int k = 1; k <= 3; ++k) EXPECT_GT(count_layer(s, k), 0);
  for (std::size_t i = s.surface_count(); i < s.position.size(); ++i) {
    EXPECT_NEAR(s.position[i].norm(), r - s.layer[i] * dx, 1e-12);
  }
}

TEST(BodySampling, SmallSpheresStayClosedWithPositiveAreas) {
  const double dx = 0.1;
  for (double r : {0.03, 0.05, 0.08, 0.1, 0.13, 0.2, 0.37, 0.61}) {
    const BodySample s = sample_sphere_body(r, dx, 2, 3);
    expect_well_formed(s);
    const double area = 4 * kPi * r * r;
    EXPECT_NEAR(total_area(s), area, 1e-9 * area) << r;
    EXPECT_LE(total_area_vector(s).norm(), 1e-9 * area) << r;
    for (std::size_t i = 0; i < s.surface_count(); ++i) {
      EXPECT_NEAR(s.position[i].norm(), r, 1e-12);
      EXPECT_GT(s.area[i], 0.5 * area / s.surface_count());
    }
  }
  // Radius 0.22: layer 1 is the sphere of radius 0.12; layer 2 (radius 0.02 < dx/4) is the
  // centre alone; nothing deeper.
  const BodySample s = sample_sphere_body(0.22, dx, 5, 3);
  EXPECT_GT(count_layer(s, 1), 4);
  ASSERT_EQ(count_layer(s, 2), 1);
  EXPECT_EQ(s.position.back(), Vec3::Zero());
  EXPECT_EQ(count_layer(s, 3), 0);
}

TEST(BodySampling, Sphere2DIsTheCircleInTheXzPlane) {
  const double r = 0.5, dx = 0.05;
  const BodySample s = sample_sphere_body(r, dx, 2, 2);
  expect_well_formed(s);
  ASSERT_EQ(s.surface_count(), 63u);  // round(2 pi r / dx)
  EXPECT_NEAR(total_area(s), 2 * kPi * r, 1e-12);
  EXPECT_LE(total_area_vector(s).norm(), 1e-12);
  for (std::size_t i = 0; i < s.position.size(); ++i) {
    EXPECT_EQ(s.position[i][1], 0.0);
    EXPECT_NEAR(s.position[i].norm(), r - s.layer[i] * dx, 1e-12);
    if (s.layer[i] == 0) {
      EXPECT_LE((s.normal[i] - s.position[i] / r).norm(), 1e-12);
      EXPECT_NEAR(s.area[i], 2 * kPi * r / 63, 1e-15);
    }
  }
  EXPECT_EQ(count_layer(s, 1), 57);  // round(2 pi 0.45 / 0.05)
  expect_spacing_about(s, dx);
}

// ---------------------------------------------------------------------------------------------
// Cylinders

TEST(BodySampling, CylinderHasSideAndCapsWithTheirOwnNormals) {
  const double r = 0.3, len = 1.0, dx = 0.05;
  const BodySample s = sample_cylinder_body(r, len, dx, 2, 3);
  expect_well_formed(s);
  const double area = 2 * kPi * r * len + 2 * kPi * r * r;
  EXPECT_NEAR(total_area(s), area, 1e-9 * area);
  EXPECT_LE(total_area_vector(s).norm(), 1e-9 * area);
  int side = 0, top = 0, bottom = 0;
  for (std::size_t i = 0; i < s.surface_count(); ++i) {
    const Vec3& p = s.position[i];
    const Vec3& n = s.normal[i];
    const double rho = std::hypot(p[0], p[1]);
    if (n[2] == 1.0 || n[2] == -1.0) {  // cap: on the end plane, within the radius
      EXPECT_EQ(p[2], 0.5 * len * n[2]);
      EXPECT_LT(rho, r);
      ++(n[2] > 0 ? top : bottom);
    } else {  // side: on the mantle, radial normal
      ++side;
      EXPECT_NEAR(rho, r, 1e-12);
      EXPECT_LT(std::abs(p[2]), 0.5 * len);
      EXPECT_EQ(n[2], 0.0);
      EXPECT_LE((n - Vec3(p[0], p[1], 0) / rho).norm(), 1e-12);
    }
    EXPECT_GT(p.dot(n), 0.0);
  }
  EXPECT_EQ(side, 38 * 20);  // round(2 pi r / dx) x round(len / dx)
  EXPECT_EQ(top, bottom);
  expect_spacing_about(s, dx);
  for (std::size_t i = s.surface_count(); i < s.position.size(); ++i) {
    const Vec3& p = s.position[i];
    const double depth = std::min(r - std::hypot(p[0], p[1]), 0.5 * len - std::abs(p[2]));
    EXPECT_NEAR(depth, s.layer[i] * dx, 1e-12);
  }
  EXPECT_GT(count_layer(s, 2), 0);
}

TEST(BodySampling, CylinderCapsAloneTileTheDisc) {
  const double dx = 0.1;
  for (double r : {0.04, 0.1, 0.17, 0.5, 1.23}) {
    const BodySample s = sample_cylinder_body(r, 0.6, dx, 0, 3);
    double cap = 0;
    for (std::size_t i = 0; i < s.surface_count(); ++i) {
      if (s.normal[i][2] == 1.0) cap += s.area[i];
    }
    EXPECT_NEAR(cap, kPi * r * r, 1e-12) << r;
    EXPECT_LE(total_area_vector(s).norm(), 1e-12) << r;
  }
  // Thin interiors: radius 0.12 leaves an axis line at layer 1; length 0.2 a disc at z = 0.
  const BodySample line = sample_cylinder_body(0.12, 1.0, dx, 3, 3);
  EXPECT_EQ(count_layer(line, 1), 8);
  for (std::size_t i = line.surface_count(); i < line.position.size(); ++i) {
    EXPECT_EQ(line.position[i][0], 0.0);
  }
  const BodySample disc = sample_cylinder_body(0.5, 0.2, dx, 3, 3);
  EXPECT_GT(count_layer(disc, 1), 0);
  EXPECT_EQ(count_layer(disc, 2), 0);
  for (std::size_t i = disc.surface_count(); i < disc.position.size(); ++i) {
    EXPECT_EQ(disc.position[i][2], 0.0);
  }
}

TEST(BodySampling, Cylinder2DIsTheCircleOfItsRadius) {
  const BodySample c = sample_cylinder_body(0.5, 7.0, 0.05, 2, 2);
  const BodySample s = sample_sphere_body(0.5, 0.05, 2, 2);
  ASSERT_EQ(c.position.size(), s.position.size());
  for (std::size_t i = 0; i < c.position.size(); ++i) {
    EXPECT_EQ(c.position[i], s.position[i]);
    EXPECT_EQ(c.normal[i], s.normal[i]);
    EXPECT_EQ(c.area[i], s.area[i]);
  }
}

// ---------------------------------------------------------------------------------------------
// Triangle meshes

// Box mesh centred at the origin; `shared` false gives every triangle its own three vertices.
TriangleMesh box_mesh(const Vec3& size, bool shared = true) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i) {
    m.vertices.push_back(0.5 * Vec3((i & 1 ? 1 : -1) * size[0], (i & 2 ? 1 : -1) * size[1],
                                    (i & 4 ? 1 : -1) * size[2]));
  }
  const std::array<std::array<std::uint32_t, 4>, 6> quads = {{
      {0, 4, 6, 2},
      {1, 3, 7, 5},  // x-, x+
      {0, 1, 5, 4},
      {2, 6, 7, 3},  // y-, y+
      {0, 2, 3, 1},
      {4, 5, 7, 6},  // z-, z+
  }};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  if (!shared) {
    TriangleMesh soup;
    for (const auto& t : m.triangles) {
      const auto base = static_cast<std::uint32_t>(soup.vertices.size());
      for (std::uint32_t v : t) soup.vertices.push_back(m.vertices[v]);
      soup.triangles.push_back({base, base + 1, base + 2});
    }
    return soup;
  }
  return m;
}

TriangleMesh octahedron(double a) {
  TriangleMesh m;
  m.vertices = {Vec3(a, 0, 0),  Vec3(-a, 0, 0), Vec3(0, a, 0),
                Vec3(0, -a, 0), Vec3(0, 0, a),  Vec3(0, 0, -a)};
  for (std::uint32_t x : {0u, 1u}) {
    for (std::uint32_t y : {2u, 3u}) {
      for (std::uint32_t z : {4u, 5u}) {
        // Counter-clockwise seen from outside when the octant's orientation is positive.
        const Vec3 n = m.vertices[x] + m.vertices[y] + m.vertices[z];
        const Vec3 c = (m.vertices[y] - m.vertices[x]).cross(m.vertices[z] - m.vertices[x]);
        if (c.dot(n) > 0) {
          m.triangles.push_back({x, y, z});
        } else {
          m.triangles.push_back({x, z, y});
        }
      }
    }
  }
  return m;
}

// An L-shaped prism: the polygon (0,0) (2,0) (2,1) (1,1) (1,2) (0,2) times `s`, z in [0, h].
const std::vector<Eigen::Vector2d> kL = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};

TriangleMesh l_prism(double s, double h) {
  TriangleMesh m;
  for (double z : {0.0, h}) {
    for (const auto& q : kL) m.vertices.push_back(Vec3(s * q[0], s * q[1], z));
  }
  const std::array<std::array<std::uint32_t, 3>, 4> cap = {
      {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}}};
  for (const auto& t : cap) {
    m.triangles.push_back({t[0], t[2], t[1]});              // bottom, facing -z
    m.triangles.push_back({t[0] + 6, t[1] + 6, t[2] + 6});  // top, facing +z
  }
  for (std::uint32_t i = 0; i < 6; ++i) {
    const std::uint32_t j = (i + 1) % 6;
    m.triangles.push_back({i, j, j + 6});
    m.triangles.push_back({i, j + 6, i + 6});
  }
  return m;
}

double mesh_area(const TriangleMesh& m) {
  double sum = 0;
  for (const auto& t : m.triangles) {
    const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    sum += 0.5 * (b - a).cross(c - a).norm();
  }
  return sum;
}

// Distance from p to the nearest triangle, and that triangle's unit normal.
std::pair<double, Vec3> nearest_triangle(const TriangleMesh& m, const Vec3& p) {
  double best = 1e300;
  Vec3 normal = Vec3::Zero();
  for (const auto& t : m.triangles) {
    const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    const Vec3 n = (b - a).cross(c - a).normalized();
    // Inside test on the projection, else nearest point of the edges (sampled finely enough to
    // bound distances here well below the tolerances used).
    const Vec3 q = p - n * n.dot(p - a);
    double d;
    if ((b - a).cross(q - a).dot(n) >= -1e-15 && (c - b).cross(q - b).dot(n) >= -1e-15 &&
        (a - c).cross(q - c).dot(n) >= -1e-15) {
      d = std::abs(n.dot(p - a));
    } else {
      d = 1e300;
      for (const auto& [u, v] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
        const double s = std::clamp((p - u).dot(v - u) / (v - u).squaredNorm(), 0.0, 1.0);
        d = std::min(d, (u + s * (v - u) - p).norm());
      }
    }
    if (d < best) {
      best = d;
      normal = n;
    }
  }
  return {best, normal};
}

// Surface particles lie on the mesh with the normal of the triangle they lie on; areas and area
// vectors add up.
void expect_mesh_surface(const TriangleMesh& mesh, const BodySample& s) {
  expect_well_formed(s);
  const double area = mesh_area(mesh);
  EXPECT_NEAR(total_area(s), area, 1e-9 * area);
  EXPECT_LE(total_area_vector(s).norm(), 1e-9 * area);
  for (std::size_t i = 0; i < s.surface_count(); ++i) {
    const auto [d, n] = nearest_triangle(mesh, s.position[i]);
    EXPECT_LE(d, 1e-12);
    EXPECT_LE((s.normal[i] - n).norm(), 1e-9) << s.position[i].transpose();
  }
}

using Particle = std::tuple<double, double, double, double, double, double, double>;

std::vector<Particle> sorted_surface(const BodySample& s) {
  std::vector<Particle> out;
  for (std::size_t i = 0; i < s.surface_count(); ++i) {
    const Vec3& p = s.position[i];
    const Vec3& n = s.normal[i];
    // Rounded so that last-bit differences do not change the order.
    auto r = [](double x) { return std::round(x * 1e9) / 1e9; };
    out.emplace_back(r(p[0]), r(p[1]), r(p[2]), n[0], n[1], n[2], s.area[i]);
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(BodySampling, BoxShapedMeshSamplesLikeTheBox) {
  const Vec3 size(1.0, 0.6, 0.4);
  const double dx = 0.1;
  const BodySample box = sample_box_body(size, dx, 0, 3);
  for (bool shared : {true, false}) {
    const TriangleMesh mesh = box_mesh(size, shared);
    const BodySample s = sample_mesh_body(mesh, dx, 0);
    expect_mesh_surface(mesh, s);
    ASSERT_EQ(s.surface_count(), box.surface_count());
    const auto a = sorted_surface(s), b = sorted_surface(box);
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_NEAR(std::get<0>(a[i]), std::get<0>(b[i]), 1e-12);
      EXPECT_NEAR(std::get<1>(a[i]), std::get<1>(b[i]), 1e-12);
      EXPECT_NEAR(std::get<2>(a[i]), std::get<2>(b[i]), 1e-12);
      EXPECT_NEAR(std::get<3>(a[i]), std::get<3>(b[i]), 1e-12);
      EXPECT_NEAR(std::get<4>(a[i]), std::get<4>(b[i]), 1e-12);
      EXPECT_NEAR(std::get<5>(a[i]), std::get<5>(b[i]), 1e-12);
      EXPECT_NEAR(std::get<6>(a[i]), std::get<6>(b[i]), 1e-14);
    }
    // Also for sides that are not multiples of dx.
    const Vec3 odd(1.03, 0.57, 0.41);
    const BodySample m2 = sample_mesh_body(box_mesh(odd, shared), dx, 0);
    const BodySample b2 = sample_box_body(odd, dx, 0, 3);
    ASSERT_EQ(m2.surface_count(), b2.surface_count());
    const auto c = sorted_surface(m2), d = sorted_surface(b2);
    for (std::size_t i = 0; i < c.size(); ++i) {
      EXPECT_NEAR(std::get<0>(c[i]), std::get<0>(d[i]), 1e-9);
      EXPECT_NEAR(std::get<6>(c[i]), std::get<6>(d[i]), 1e-14);
    }
  }
}

TEST(BodySampling, BoxShapedMeshInteriorIsTheLatticeBand) {
  const Vec3 size(1.0, 0.6, 0.4);
  const double dx = 0.1;
  const BodySample s = sample_mesh_body(box_mesh(size), dx, 2);
  expect_well_formed(s);
  // Lattice nodes -0.5 + 0.1 i etc.: depth 0.1 -> 9 x 5 x 3 minus 7 x 3 x 1; depth 0.2 -> 21.
  EXPECT_EQ(count_layer(s, 1), 9 * 5 * 3 - 7 * 3 * 1);
  EXPECT_EQ(count_layer(s, 2), 7 * 3 * 1);
  for (std::size_t i = s.surface_count(); i < s.position.size(); ++i) {
    EXPECT_NEAR(box_depth(s.position[i], size, {0, 1, 2}), s.layer[i] * dx, 1e-12);
  }
  // Within a few percent of the box's own shells (112 + 12).
  const BodySample box = sample_box_body(size, dx, 2, 3);
  const double mesh_interior = static_cast<double>(s.position.size() - s.surface_count());
  const double box_interior = static_cast<double>(box.position.size() - box.surface_count());
  EXPECT_NEAR(mesh_interior / box_interior, 1.0, 0.1);
}

TEST(BodySampling, OctahedronFacesAreTiledWithClippedCells) {
  const double a = 0.5, dx = 0.05;
  const TriangleMesh mesh = octahedron(a);
  const BodySample s = sample_mesh_body(mesh, dx, 3);
  expect_mesh_surface(mesh, s);
  for (std::size_t i = 0; i < s.surface_count(); ++i) {
    EXPECT_GT(s.position[i].dot(s.normal[i]), 0.0);
  }
  // About one particle per dx^2 of surface.
  const double expected = mesh_area(mesh) / (dx * dx);
  EXPECT_NEAR(static_cast<double>(s.surface_count()) / expected, 1.0, 0.15);
  // Cells cut by the tilted edges leave pieces whose centroids come to about 0.4 dx of a
  // neighbour (same face near a corner, or across an edge).
  const auto [lo, hi] = nearest_neighbour_range(s);
  EXPECT_GE(lo, 0.35 * dx);
  EXPECT_LE(hi, 1.5 * dx);
  for (int k = 1; k <= 3; ++k) EXPECT_GT(count_layer(s, k), 0);
  for (std::size_t i = s.surface_count(); i < s.position.size(); ++i) {
    const Vec3& p = s.position[i];
    const double depth = (a - p.cwiseAbs().sum()) / std::sqrt(3.0);
    EXPECT_GE(depth, 0.5 * dx - 1e-12);
    EXPECT_LT(depth, 3.5 * dx);
    EXPECT_EQ(s.layer[i], std::lround(depth / dx));
  }
}

// Signed distance to the L polygon's boundary (positive inside).
double l_depth_2d(double s, double x, double y) {
  double d = 1e300;
  for (std::size_t i = 0; i < kL.size(); ++i) {
    const Eigen::Vector2d u = s * kL[i], v = s * kL[(i + 1) % kL.size()], p(x, y);
    const double t = std::clamp((p - u).dot(v - u) / (v - u).squaredNorm(), 0.0, 1.0);
    d = std::min(d, (u + t * (v - u) - p).norm());
  }
  const bool inside = x > 0 && y > 0 && x < 2 * s && y < 2 * s && (x < s || y < s);
  return inside ? d : -d;
}

TEST(BodySampling, NonConvexPrismKeepsItsFacesAndInterior) {
  const double sc = 0.5, h = 0.3, dx = 0.1;
  const TriangleMesh mesh = l_prism(sc, h);
  const BodySample s = sample_mesh_body(mesh, dx, 2);
  expect_mesh_surface(mesh, s);
  // Caps: 75 cells each; walls: 10 x 3 twice, 5 x 3 four times.
  EXPECT_EQ(s.surface_count(), 2u * 75u + 2u * 30u + 4u * 15u);
  expect_spacing_about(s, dx);
  EXPECT_GT(count_layer(s, 1), 0);
  for (std::size_t i = s.surface_count(); i < s.position.size(); ++i) {
    const Vec3& p = s.position[i];
    const double depth = std::min({l_depth_2d(sc, p[0], p[1]), p[2], h - p[2]});
    EXPECT_GE(depth, 0.5 * dx - 1e-12) << p.transpose();
    EXPECT_LT(depth, 2.5 * dx);
  }
  // Every lattice node (multiples of dx from the bounding box's corner) in the band is there.
  int expected = 0;
  for (int i = 0; i <= 10; ++i) {
    for (int j = 0; j <= 10; ++j) {
      for (int k = 0; k <= 3; ++k) {
        const double depth = std::min({l_depth_2d(sc, i * dx, j * dx), k * dx, h - k * dx});
        if (depth >= 0.5 * dx && depth < 2.5 * dx) ++expected;
      }
    }
  }
  EXPECT_EQ(static_cast<int>(s.position.size() - s.surface_count()), expected);

  // Turned and moved, the same mesh gives the same number of particles and stays closed.
  const Eigen::Matrix3d rot = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  TriangleMesh turned = mesh;
  for (Vec3& v : turned.vertices) v = rot * v + Vec3(0.3, -1.1, 2.0);
  const BodySample t = sample_mesh_body(turned, dx, 2);
  expect_mesh_surface(turned, t);
  EXPECT_EQ(t.surface_count(), s.surface_count());
}

TEST(BodySampling, TiltedTrianglesWithSliversStayOnTheSurface) {
  // A tetrahedron with unequal edges: its faces are cut by the grid into many partial cells.
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(0.93, 0.1, 0.05), Vec3(0.2, 0.71, -0.1), Vec3(0.3, 0.25, 0.66)};
  m.triangles = {{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {0, 2, 3}};
  const Vec3 centre = (m.vertices[0] + m.vertices[1] + m.vertices[2] + m.vertices[3]) / 4;
  for (auto& t : m.triangles) {  // wind counter-clockwise seen from outside
    const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    if ((b - a).cross(c - a).dot(a - centre) < 0) std::swap(t[1], t[2]);
  }
  for (double dx : {0.3, 0.1, 0.037}) {
    const BodySample s = sample_mesh_body(m, dx, 1);
    expect_mesh_surface(m, s);
  }
}

TEST(BodySampling, RejectsBadArguments) {
  EXPECT_THROW(sample_box_body(Vec3(1, 1, 1), 0.0, 1, 3), std::invalid_argument);
  EXPECT_THROW(sample_box_body(Vec3(1, -1, 1), 0.1, 1, 3), std::invalid_argument);
  EXPECT_THROW(sample_box_body(Vec3(1, 1, 1), 0.1, -1, 3), std::invalid_argument);
  EXPECT_THROW(sample_box_body(Vec3(1, 1, 1), 0.1, 1, 1), std::invalid_argument);
  EXPECT_NO_THROW(sample_box_body(Vec3(1, 0, 1), 0.1, 1, 2));  // y unused in 2D
  EXPECT_THROW(sample_sphere_body(0.0, 0.1, 1, 3), std::invalid_argument);
  EXPECT_THROW(sample_sphere_body(1.0, std::nan(""), 1, 3), std::invalid_argument);
  EXPECT_THROW(sample_cylinder_body(1.0, 0.0, 0.1, 1, 3), std::invalid_argument);
  EXPECT_THROW(sample_mesh_body(TriangleMesh{}, 0.1, 1), std::invalid_argument);
  TriangleMesh bad = box_mesh(Vec3(1, 1, 1));
  bad.triangles.push_back({0, 1, 99});
  EXPECT_THROW(sample_mesh_body(bad, 0.1, 1), std::invalid_argument);
}

}  // namespace
}  // namespace sluice
