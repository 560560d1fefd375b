// Building contact bodies from sampled shapes: a free body from a shape's surface particles and
// mass properties; fixed walls (a patch of floor, a tank's sides, a plane, a solid box).
#pragma once

#include <string>
#include <vector>

#include "sluice/contact/contact_body.hpp"
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

// The closed sides of a tank (`inside` is its inner box; `open_sides` among "x-", "x+", "y-",
// "y+", "z-", "z+") as fixed bodies, one per side, their surface particles on the inner faces
// facing into the tank. One body per side keeps each side's bounding box flat, so a body is "in
// reach" of a side only when it is near that side. dimension 2: the x-z section (no y sides).
std::vector<ContactBody> make_tank_walls(const Vec3& inside_min, const Vec3& inside_max,
                                         const std::vector<std::string>& open_sides, double dx,
                                         const ContactMaterial& material, int dimension = 3);

// A plane wall through `point` with unit `normal` (out of the solid) as one fixed body: its
// part inside [lo, hi] tiled with surface particles of spacing dx (dimension 2: the line in the
// x-z plane, lo and hi in x and z).
ContactBody make_plane_wall(const Vec3& point, const Vec3& normal, const Vec3& lo, const Vec3& hi,
                            double dx, const ContactMaterial& material, int dimension);

// A solid box [box_min, box_max] as one fixed body, its surface particles facing out.
ContactBody make_fixed_box(const Vec3& box_min, const Vec3& box_max, double dx,
                           const ContactMaterial& material, int dimension);

}  // namespace sluice
