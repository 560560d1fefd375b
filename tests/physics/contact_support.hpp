// Bodies for the contact checks: shapes sampled with the project's own samplers, a floor.
#pragma once

#include <cmath>

#include "sluice/contact/multibody_system.hpp"
#include "sluice/geometry/body_sampling.hpp"
#include "sluice/rigid/mass_properties.hpp"

namespace sluice::testing {

// A free body from a shape's surface particles and mass properties (principal axes along the
// shape's own, as for boxes and spheres).
inline ContactBody body_from_sample(const BodySample& sample, const MassProperties& mass,
                                    const ContactMaterial& material, double contact_radius) {
  ContactBody body;
  body.material = material;
  body.state.mass = mass.mass;
  body.state.principal_inertia = mass.inertia.diagonal();
  body.contact_radius = contact_radius;
  for (std::size_t k = 0; k < sample.surface_count(); ++k) {
    body.surface_position.push_back(sample.position[k] - mass.center_of_mass);
    body.surface_normal.push_back(sample.normal[k]);
    body.surface_area.push_back(sample.area[k]);
  }
  return body;
}

// A curved body: a sphere of water-like density 1000 kg/m^3.
inline ContactBody sphere_body(double radius, double dx, const ContactMaterial& material) {
  ContactBody body = body_from_sample(sample_sphere_body(radius, dx, 0, 3),
                                      sphere_mass_properties(radius, 1000.0), material, radius);
  body.flat_faces = false;
  return body;
}

// The floor z = 0 as a fixed body: a square of surface particles facing up.
inline ContactBody floor_patch(double half_width, double dx, const ContactMaterial& material) {
  ContactBody floor;
  floor.fixed = true;
  floor.material = material;
  const int n = static_cast<int>(std::lround(2 * half_width / dx));
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      floor.surface_position.push_back(
          Vec3(-half_width + (i + 0.5) * dx, -half_width + (j + 0.5) * dx, 0));
      floor.surface_normal.push_back(Vec3::UnitZ());
      floor.surface_area.push_back(dx * dx);
    }
  }
  return floor;
}

}  // namespace sluice::testing
