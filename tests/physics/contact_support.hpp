// Bodies for the contact checks, built with the library's own builders.
#pragma once

#include "sluice/contact/contact_body_builder.hpp"
#include "sluice/contact/multibody_system.hpp"

namespace sluice::testing {

// A curved body: a sphere of density 1000 kg/m^3.
inline ContactBody sphere_body(double radius, double dx, const ContactMaterial& material) {
  ContactBody sphere =
      make_contact_body(sample_sphere_body(radius, dx, 0, 3),
                        sphere_mass_properties(radius, 1000.0), material, radius, false);
  sphere.spherical = true;
  return sphere;
}

inline ContactBody floor_patch(double half_width, double dx, const ContactMaterial& material) {
  return make_floor_patch(half_width, dx, material);
}

}  // namespace sluice::testing
