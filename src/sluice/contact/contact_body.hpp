// What contact knows of a body: its surface particles with the outward normal and area of the
// face each samples (in the principal frame, relative to the centre of mass), its material and
// curvature. A ContactBody is such a shape together with the rigid system's body, for building
// a system body by body.
#pragma once

#include <optional>
#include <vector>

#include "sluice/contact/contact_material.hpp"
#include "sluice/rigid/body_interaction.hpp"

namespace sluice {

// The solid side of a plane wall: the points x with (x - point) . normal < 0.
struct HalfSpace {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  // unit, out of the solid
};

struct ContactShape {
  ContactMaterial material;
  double contact_radius = 0;  // R in Hertz's law; 0 = flat (a wall)
  bool flat_faces = true;     // every surface particle lies on a plane face (boxes, meshes, walls)
  // A sphere (2D: a disc) of radius contact_radius about the centre of mass: its overlap is
  // then computed exactly from its centre, smooth as it rolls or glances off.
  bool spherical = false;
  // A plane wall: reach is measured to its plane, since the bounding box of a sloping plane
  // spans the domain and would put every body in reach.
  std::optional<HalfSpace> half_space;
  std::vector<Vec3> surface_position;
  std::vector<Vec3> surface_normal;
  std::vector<double> surface_area;
};

struct ContactBody : SystemBody, ContactShape {};

}  // namespace sluice
