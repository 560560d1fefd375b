#include "sluice/rigid/mass_properties.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace sluice {

namespace {

void require_positive(double value, const char* function, const char* what) {
  if (!(std::isfinite(value) && value > 0)) {
    throw std::invalid_argument(std::string(function) + ": " + what +
                                " must be positive and finite, got " + std::to_string(value));
  }
}

}  // namespace

MassProperties box_mass_properties(const Vec3& size, double density) {
  for (int i = 0; i < 3; ++i) require_positive(size[i], "box_mass_properties", "size");
  require_positive(density, "box_mass_properties", "density");
  const Vec3 sq = size.cwiseProduct(size);
  MassProperties p;
  p.mass = density * size.prod();
  p.inertia.diagonal() = Vec3(sq.y() + sq.z(), sq.x() + sq.z(), sq.x() + sq.y()) * (p.mass / 12);
  return p;
}

MassProperties sphere_mass_properties(double radius, double density) {
  require_positive(radius, "sphere_mass_properties", "radius");
  require_positive(density, "sphere_mass_properties", "density");
  MassProperties p;
  p.mass = density * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  p.inertia.diagonal().setConstant(0.4 * p.mass * radius * radius);
  return p;
}

MassProperties cylinder_mass_properties(double radius, double length, double density) {
  require_positive(radius, "cylinder_mass_properties", "radius");
  require_positive(length, "cylinder_mass_properties", "length");
  require_positive(density, "cylinder_mass_properties", "density");
  MassProperties p;
  p.mass = density * std::numbers::pi * radius * radius * length;
  const double across = p.mass * (3 * radius * radius + length * length) / 12;
  p.inertia.diagonal() = Vec3(across, across, 0.5 * p.mass * radius * radius);
  return p;
}

MassProperties mesh_mass_properties(const TriangleMesh& mesh, double density) {
  require_positive(density, "mesh_mass_properties", "density");
  // Integrate relative to the vertex mean: keeps the sums well conditioned for meshes placed
  // far from the origin.
  Vec3 ref = Vec3::Zero();
  for (const Vec3& v : mesh.vertices) ref += v;
  if (!mesh.vertices.empty()) ref /= static_cast<double>(mesh.vertices.size());

  // For the tetrahedron (ref, a, b, c) with det = a . (b x c) = 6 V:
  //   int 1 = det / 6,  int x = det (a + b + c) / 24,
  //   int x x^T = det / 120 (a a^T + b b^T + c c^T + s s^T), s = a + b + c
  // (Tonon, "Explicit exact formulas for the 3-D tetrahedron inertia tensor", J. Math. Stat. 2004).
  double six_volume = 0;
  Vec3 first = Vec3::Zero();                         // times 24
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();  // times 120
  const auto n = mesh.vertices.size();
  for (const auto& t : mesh.triangles) {
    if (t[0] >= n || t[1] >= n || t[2] >= n) {
      throw std::invalid_argument("mesh_mass_properties: triangle references a missing vertex");
    }
    const Vec3 a = mesh.vertices[t[0]] - ref;
    const Vec3 b = mesh.vertices[t[1]] - ref;
    const Vec3 c = mesh.vertices[t[2]] - ref;
    const Vec3 s = a + b + c;
    const double det = a.dot(b.cross(c));
    six_volume += det;
    first += det * s;
    second += det * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  const double volume = six_volume / 6;
  if (!(std::isfinite(volume) && volume > 0)) {
    throw std::invalid_argument("mesh_mass_properties: the mesh encloses no positive volume (" +
                                std::to_string(volume) + "); is it empty or wound inward?");
  }
  const Vec3 com = first / (24 * volume);  // relative to ref
  MassProperties p;
  p.mass = density * volume;
  p.center_of_mass = ref + com;
  // Second moment about the centre of mass (parallel-axis shift), then I = tr(C) 1 - C.
  Eigen::Matrix3d c_com = density / 120 * second - p.mass * com * com.transpose();
  c_com = 0.5 * (c_com + c_com.transpose());
  p.inertia = c_com.trace() * Eigen::Matrix3d::Identity() - c_com;
  return p;
}

MassProperties with_mass(MassProperties p, double mass) {
  require_positive(p.mass, "with_mass", "the shape's mass");
  require_positive(mass, "with_mass", "mass");
  p.inertia *= mass / p.mass;
  p.mass = mass;
  return p;
}

}  // namespace sluice
