// Reading closed triangle meshes (STL, OBJ) for rigid bodies, and checks on them.
#pragma once

#include <string>

#include "sluice/geometry/triangle_mesh.hpp"

namespace sluice {

// Reads an STL (ASCII or binary) or OBJ file with Assimp. All meshes of the file are
// concatenated (node transforms are not applied), polygons are triangulated, and vertices at
// exactly the same position are merged, also across meshes; points and lines are ignored.
// Vertices are multiplied by `scale`. A closed mesh wound inward (negative volume) is flipped.
// Throws InputError(case_file, line, key, problem), the problem naming `mesh_path`, when the
// scale is not positive, or the file is missing, unreadable, not a mesh, has no triangles, has
// non-finite coordinates, is not closed (see is_closed), or encloses no volume.
// `mesh_path` is used as given: resolve it against the case file's folder before calling.
TriangleMesh read_mesh(const std::string& mesh_path, double scale, const std::string& case_file,
                       int line, const std::string& key);

// True when the mesh has triangles, every triangle has three distinct valid vertex indices,
// and every edge is shared by exactly two triangles that traverse it in opposite directions.
// On failure writes the reason (first offending edge in index order) to *why when non-null.
bool is_closed(const TriangleMesh& mesh, std::string* why);

// Volume enclosed by a closed mesh: positive when wound counter-clockwise seen from outside.
double signed_volume(const TriangleMesh& mesh);

}  // namespace sluice
