#include "sluice/sim/body_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sluice {

namespace {

// The radius of the sphere (2D: the disc) with the body's volume: the Hertz radius of a body
// with flat faces.
double equivalent_radius(double volume, int dimension) {
  return dimension == 2 ? std::sqrt(volume / std::numbers::pi)
                        : std::cbrt(3 * volume / (4 * std::numbers::pi));
}
}  // namespace

ShapeSample sample_shape(const io::BodyConfig& b, double dx, int dimension) {
  ShapeSample out;
  const double density = b.density > 0 ? b.density : 1.0;  // scaled to the mass below
  switch (b.shape) {
    case io::BodyShape::kBox: {
      const Vec3 size = dimension == 2 ? Vec3(b.size[0], 1.0, b.size[2]) : b.size;
      out.mass = box_mass_properties(size, density);
      out.surface = sample_box_body(size, dx, 0, dimension);
      out.contact_radius = equivalent_radius(out.mass.mass / density, dimension);
      break;
    }
    case io::BodyShape::kSphere:
    case io::BodyShape::kCylinder: {
      const bool disc = dimension == 2;  // 2D: a circle, i.e. a cylinder along y, unit depth
      const bool sphere = b.shape == io::BodyShape::kSphere && !disc;
      if (sphere) {
        out.mass = sphere_mass_properties(b.radius, density);
        out.surface = sample_sphere_body(b.radius, dx, 0, 3);
      } else {
        const double length = disc ? 1.0 : b.length;
        out.mass = cylinder_mass_properties(b.radius, length, density);
        if (disc) std::swap(out.mass.inertia(1, 1), out.mass.inertia(2, 2));  // axis along y
        out.surface = sample_cylinder_body(b.radius, length, dx, 0, dimension);
      }
      out.contact_radius = b.radius;
      out.flat_faces = false;
      out.spherical = sphere || disc;
      break;
    }
    case io::BodyShape::kMesh: {
      out.mass = mesh_mass_properties(b.mesh, density);
      out.surface = sample_mesh_body(b.mesh, dx, 0);
      out.contact_radius = equivalent_radius(out.mass.mass / density, 3);
      break;
    }
  }
  if (b.mass > 0) out.mass = with_mass(out.mass, b.mass);
  return out;
}

std::vector<Vec3> sample_under_surface(const io::BodyConfig& b, double dx, int layers,
                                       int dimension) {
  const double half = 0.5 * dx;
  switch (b.shape) {
    case io::BodyShape::kBox: {
      const Vec3 size = dimension == 2 ? Vec3(b.size[0], 1.0, b.size[2]) : b.size;
      const Vec3 inner = (size.array() - dx).cwiseMax(half).matrix();
      return sample_box_body(inner, dx, layers - 1, dimension).position;
    }
    case io::BodyShape::kSphere:
    case io::BodyShape::kCylinder: {
      const bool disc = dimension == 2;
      if (b.shape == io::BodyShape::kSphere && !disc)
        return sample_sphere_body(std::max(b.radius - half, half), dx, layers - 1, 3).position;
      const double length = disc ? 1.0 : b.length;
      return sample_cylinder_body(std::max(b.radius - half, half), std::max(length - dx, half), dx,
                                  layers - 1, dimension)
          .position;
    }
    case io::BodyShape::kMesh: {
      const BodySample all = sample_mesh_body(b.mesh, dx, layers);
      std::vector<Vec3> out;
      for (std::size_t k = 0; k < all.position.size(); ++k) {
        if (all.layer[k] >= 1) out.push_back(all.position[k]);  // depth dx/2 and below
      }
      return out;
    }
  }
  return {};
}

}  // namespace sluice
