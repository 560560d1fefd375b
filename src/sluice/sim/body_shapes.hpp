// A body's shape as the case gives it, sampled: its mass properties, the surface particles that
// contact uses, and the points a fluid sees under its surface.
#pragma once

#include <vector>

#include "sluice/geometry/body_sampling.hpp"
#include "sluice/io/body_config.hpp"
#include "sluice/rigid/mass_properties.hpp"

namespace sluice {

// A body's shape in its own frame: mass properties, the surface particles that contact uses,
// and the particles the fluid sees. The fluid's boundary lies half a spacing outside its wall
// particles, so those are sampled on the shape shrunk by dx/2 and below: the fluid then meets
// the true surface. (A fixed wall's particles sit likewise half a spacing behind its face.)
struct ShapeSample {
  MassProperties mass;
  BodySample surface;  // on the faces, with normals and areas (contact)
  double contact_radius = 0;
  bool flat_faces = true;
  bool spherical = false;  // a sphere, or a disc in 2D
};

// The shape of body `b` in its own frame (dimension 2: its section in the x-z plane).
ShapeSample sample_shape(const io::BodyConfig& b, double dx, int dimension);

// The points the fluid sees in a body, in the shape's frame: `layers` layers at depths dx/2,
// 3 dx/2, ... (the shape shrunk by dx/2 and below; the fluid's boundary lies half a spacing
// outside them, on the true surface).
std::vector<Vec3> sample_under_surface(const io::BodyConfig& b, double dx, int layers,
                                       int dimension);

}  // namespace sluice
