// Body particles of rigid bodies (Amaro Junior et al. 2019): surface particles that sit on the
// body's faces and carry the outward unit normal of their face and the area they stand for, plus
// interior layers so that fluid particles near the surface see full kernel support.
//
// Every surface particle belongs to exactly one face and takes that face's true normal (normals
// are never blended across box edges or mesh creases); the areas of the surface particles tile the
// surface, so they add up to its true area and the area vectors n dA of a closed surface add up
// to zero. Interior particles have a zero normal and a zero area.
#pragma once

#include <cstddef>
#include <vector>

#include "sluice/core/types.hpp"
#include "sluice/geometry/triangle_mesh.hpp"

namespace sluice {

struct BodySample {  // in the body's own frame (see each function for where its origin is)
  std::vector<Vec3> position;
  std::vector<Vec3> normal;  // outward unit normal of the face; zero for interior particles
  std::vector<double> area;  // area represented (m^2; in 2D: length per unit depth); 0 inside
  std::vector<int> layer;    // 0 = surface, 1, 2, ... = interior layers inward
  // Surface particles come first: they are position[0 .. surface_count()).
  std::size_t surface_count() const;
};

// The analytic shapes give surface particles spaced about dx on each face, placed on the surface,
// plus `interior_layers` layers at depths dx, 2 dx, ... inside, each sampled like the surface
// (normals and areas zero). Layer k of a shape of thickness T (box side, 2 x radius, cylinder
// length) has thickness e = T - 2 k dx: when |e| < dx/2 it collapses onto the shape's mid-plane
// (axis, centre), so its depth lies within k dx +- dx/4; when e <= -dx/2 it is left out (the
// previous layer's sides are then at most 1.5 dx apart), and so are the layers after it. dimension
// 2: the shape's section in the x-z plane (every point has y = 0, areas are lengths per unit
// depth); dimension 3: full surfaces. All throw std::invalid_argument when a size or dx is not
// positive and finite, interior_layers < 0, or dimension is not 2 or 3.

// Box centred at the origin with edge lengths `size` (2D: the rectangle size.x by size.z;
// size.y is ignored). A face of sides a, b gets n_a = max(1, round(a/dx)) by n_b particles at
// the centres of equal cells, each with area (a/n_a)(b/n_b); no particle sits on an edge.
BodySample sample_box_body(const Vec3& size, double dx, int interior_layers, int dimension);

// Sphere of `radius` centred at the origin (2D: the circle of that radius in the x-z plane).
// 3D: a golden-spiral set of N = max(4, round(4 pi r^2 / dx^2)) points; the areas are 4 pi r^2 / N
// nudged by a few percent at most so that the area vectors add up to exactly zero and the areas
// still add up to 4 pi r^2. 2D: N = max(3, round(2 pi r / dx)) equal arcs.
BodySample sample_sphere_body(double radius, double dx, int interior_layers, int dimension);

// Cylinder centred at the origin (3D: axis along z, `length` its full length; side plus two flat
// caps, the caps tiled by rings of equal-area cells; side particles at the centres of an
// n_theta by n_z grid of equal cells). 2D: the circle of `radius` in the x-z plane (a cylinder
// whose axis is along y), exactly as sample_sphere_body; `length` is then ignored.
BodySample sample_cylinder_body(double radius, double length, double dx, int interior_layers,
                                int dimension);

// 3D only, in the mesh's own coordinates. The mesh must be closed and wound counter-clockwise
// seen from outside. Edge-adjacent triangles with the same normal are grouped into planar faces
// (vertices at the same position count as one); each face is tiled by an n_u by n_v grid of
// equal cells (n = max(1, round(extent/dx)) along the face's longest boundary edge and across
// it), every cell clipped to the face; a clipped piece smaller than a quarter cell is merged into
// its largest neighbour. One particle per piece, at its centroid, with its area and the face
// normal. A face smaller than dx gets one particle, so triangles much smaller than dx on a curved
// mesh give particles closer than dx. The surface particles of a box-shaped mesh are exactly
// those of sample_box_body (the interiors differ: lattice here, shells there).
// Interior: the points of a lattice of spacing dx anchored at the mesh's bounding-box minimum
// that are inside the mesh (winding number) at distance d from the surface with
// dx/2 <= d < interior_layers dx + dx/2; layer = round(d/dx).
// Throws std::invalid_argument when dx is not positive and finite, interior_layers < 0, the mesh
// has no triangle of nonzero area, or a vertex index is out of range.
BodySample sample_mesh_body(const TriangleMesh& mesh, double dx, int interior_layers);

}  // namespace sluice
