// Mass, centre of mass and inertia tensor of rigid-body shapes with uniform density.
#pragma once

#include <Eigen/Core>

#include "sluice/core/types.hpp"
#include "sluice/geometry/triangle_mesh.hpp"

namespace sluice {

struct MassProperties {
  double mass = 0;
  Vec3 center_of_mass = Vec3::Zero();                 // in the shape's own frame
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  // about the centre of mass, shape frame axes
};

// All of these throw std::invalid_argument when a size or the density is not positive and finite.

// Box centred at the origin, edges along the axes; `size` holds the full edge lengths.
MassProperties box_mass_properties(const Vec3& size, double density);
// Solid sphere centred at the origin.
MassProperties sphere_mass_properties(double radius, double density);
// Solid cylinder centred at the origin, axis along z, `length` its full length.
MassProperties cylinder_mass_properties(double radius, double length, double density);

// Exact for a closed, outward-wound triangle mesh (sum over the signed tetrahedra that each
// triangle spans with a reference point). Closedness is not checked here (see is_closed).
// Throws std::invalid_argument if the enclosed volume is <= 0 (empty or inside-out mesh).
MassProperties mesh_mass_properties(const TriangleMesh& mesh, double density);

// The same mass distribution scaled to a total `mass` (for bodies given by mass instead of
// density). Throws std::invalid_argument unless both p.mass and `mass` are positive and finite.
MassProperties with_mass(MassProperties p, double mass);

}  // namespace sluice
