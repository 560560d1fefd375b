// Building contact bodies from sampled shapes: a free body from a shape's surface particles and
// mass properties, and a fixed square patch of floor.
#pragma once

#include "sluice/contact/multibody_system.hpp"
#include "sluice/geometry/body_sampling.hpp"
#include "sluice/rigid/mass_properties.hpp"

namespace sluice {

// A free body at the origin whose principal axes are the shape's own axes (boxes, spheres and
// cylinders as sampled; a general mesh needs its inertia diagonalised first).
ContactBody make_contact_body(const BodySample& sample, const MassProperties& mass,
                              const ContactMaterial& material, double contact_radius,
                              bool flat_faces);

// The plane z = 0 over [-half_width, half_width]^2 as a fixed body facing up (+z).
ContactBody make_floor_patch(double half_width, double dx, const ContactMaterial& material);

}  // namespace sluice
