#include "sluice/geometry/mesh_io.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <system_error>
#include <utility>
#include <vector>

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include "sluice/core/errors.hpp"

namespace sluice {

namespace {

std::string point_text(const Vec3& p) {
  return fmt::format("({:g}, {:g}, {:g})", p.x(), p.y(), p.z());
}

// Directed use of an undirected edge (lo < hi) by one triangle.
struct EdgeUse {
  std::uint32_t lo;
  std::uint32_t hi;
  bool forward;  // the triangle goes lo -> hi
};

}  // namespace

bool is_closed(const TriangleMesh& mesh, std::string* why) {
  auto fail = [why](std::string reason) {
    if (why != nullptr) *why = std::move(reason);
    return false;
  };
  if (mesh.triangles.empty()) return fail("the mesh has no triangles");
  const auto n = mesh.vertices.size();
  std::vector<EdgeUse> uses;
  uses.reserve(3 * mesh.triangles.size());
  for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
    const auto& t = mesh.triangles[k];
    for (int e = 0; e < 3; ++e) {
      if (t[e] >= n) {
        return fail(fmt::format("triangle {} refers to vertex {}, but there are only {} vertices",
                                k, t[e], n));
      }
    }
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      return fail(fmt::format("triangle {} ({}, {}, {}) repeats a vertex", k, t[0], t[1], t[2]));
    }
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = t[e];
      const std::uint32_t b = t[(e + 1) % 3];
      uses.push_back({std::min(a, b), std::max(a, b), a < b});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& x, const EdgeUse& y) {
    return std::pair(x.lo, x.hi) < std::pair(y.lo, y.hi);
  });

  std::size_t bad_edges = 0;
  std::string first_reason;
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    std::size_t forward = 0;
    while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi) {
      forward += uses[j].forward ? 1 : 0;
      ++j;
    }
    const std::size_t count = j - i;
    if (count != 2 || forward != 1) {
      if (bad_edges == 0) {
        const auto lo = uses[i].lo;
        const auto hi = uses[i].hi;
        const std::string where = fmt::format(" (from {} to {})", point_text(mesh.vertices[lo]),
                                              point_text(mesh.vertices[hi]));
        if (count != 2) {
          first_reason = fmt::format("edge ({}, {}) is used by {} triangle{}{}", lo, hi, count,
                                     count == 1 ? "" : "s", where);
        } else {
          first_reason = fmt::format("triangles around edge ({}, {}) disagree in orientation{}", lo,
                                     hi, where);
        }
      }
      ++bad_edges;
    }
    i = j;
  }
  if (bad_edges == 0) return true;
  if (bad_edges > 1) {
    first_reason += fmt::format(
        "; {} edges in all are not shared by exactly two oppositely wound "
        "triangles",
        bad_edges);
  }
  return fail(first_reason);
}

double signed_volume(const TriangleMesh& mesh) {
  // Sum of the signed tetrahedra spanned by each triangle and a reference point (the vertex
  // mean: any point gives the same result for a closed mesh, a near one rounds less).
  Vec3 ref = Vec3::Zero();
  for (const Vec3& v : mesh.vertices) ref += v;
  if (!mesh.vertices.empty()) ref /= static_cast<double>(mesh.vertices.size());
  double six_volume = 0;
  for (const auto& t : mesh.triangles) {
    const Vec3 a = mesh.vertices.at(t[0]) - ref;
    const Vec3 b = mesh.vertices.at(t[1]) - ref;
    const Vec3 c = mesh.vertices.at(t[2]) - ref;
    six_volume += a.dot(b.cross(c));
  }
  return six_volume / 6;
}

TriangleMesh read_mesh(const std::string& mesh_path, double scale, const std::string& case_file,
                       int line, const std::string& key) {
  auto error = [&](const std::string& problem) {
    return InputError(case_file, line, key, problem);
  };
  if (!(std::isfinite(scale) && scale > 0)) {
    throw error(fmt::format("mesh scale must be positive and finite, got {}", scale));
  }

  namespace fs = std::filesystem;
  std::error_code ec;
  const auto status = fs::status(mesh_path, ec);
  if (!fs::exists(status)) {
    throw error(fmt::format("cannot read mesh file '{}': file is missing", mesh_path));
  }
  if (fs::is_directory(status)) {
    throw error(fmt::format("cannot read mesh file '{}': it is a directory", mesh_path));
  }
  if (!std::ifstream(mesh_path, std::ios::binary).good()) {
    throw error(fmt::format("cannot read mesh file '{}': cannot open it", mesh_path));
  }
  if (fs::is_regular_file(status) && fs::file_size(mesh_path, ec) == 0 && !ec) {
    throw error(fmt::format("cannot read mesh file '{}': file is empty", mesh_path));
  }

  Assimp::Importer importer;
  // Drop per-vertex attributes so that JoinIdenticalVertices merges by position alone (STL
  // gives every facet corner its facet normal).
  importer.SetPropertyInteger(AI_CONFIG_PP_RVC_FLAGS, aiComponent_NORMALS | aiComponent_TEXCOORDS |
                                                          aiComponent_COLORS |
                                                          aiComponent_TANGENTS_AND_BITANGENTS);
  const aiScene* scene =
      importer.ReadFile(mesh_path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                       aiProcess_RemoveComponent);
  if (scene == nullptr) {
    throw error(
        fmt::format("cannot read mesh file '{}': {}", mesh_path, importer.GetErrorString()));
  }

  // Concatenate the meshes, merging vertices at exactly equal positions (also across meshes,
  // which Assimp keeps apart) so that closedness can be judged on shared edges.
  TriangleMesh mesh;
  std::map<std::array<double, 3>, std::uint32_t> index_of;
  auto weld = [&](const aiVector3D& p) {
    // + 0.0 turns -0.0 into +0.0, so both map to the same vertex.
    const std::array<double, 3> key3{double(p.x) + 0.0, double(p.y) + 0.0, double(p.z) + 0.0};
    const auto [it, inserted] =
        index_of.try_emplace(key3, static_cast<std::uint32_t>(mesh.vertices.size()));
    if (inserted) mesh.vertices.emplace_back(key3[0], key3[1], key3[2]);
    return it->second;
  };
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* am = scene->mMeshes[m];
    for (unsigned f = 0; f < am->mNumFaces; ++f) {
      const aiFace& face = am->mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines
      std::array<std::uint32_t, 3> t{};
      for (int c = 0; c < 3; ++c) {
        const unsigned vi = face.mIndices[c];
        if (vi >= am->mNumVertices) {
          throw error(fmt::format("cannot read mesh file '{}': a face refers to a missing vertex",
                                  mesh_path));
        }
        const aiVector3D& p = am->mVertices[vi];
        if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))) {
          throw error(
              fmt::format("mesh file '{}' has a vertex that is not a finite number", mesh_path));
        }
        t[c] = weld(p);
      }
      // Facets that collapse to a segment or point add nothing and would spoil the edge count.
      if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
      mesh.triangles.push_back(t);
    }
  }
  if (mesh.triangles.empty()) {
    throw error(fmt::format("mesh file '{}' has no triangles", mesh_path));
  }

  std::string why;
  if (!is_closed(mesh, &why)) {
    throw error(fmt::format("mesh file '{}' is not closed: {}", mesh_path, why));
  }

  for (Vec3& v : mesh.vertices) v *= scale;
  const double volume = signed_volume(mesh);
  Vec3 lo = mesh.vertices.front();
  Vec3 hi = lo;
  for (const Vec3& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const double extent = (hi - lo).norm();
  if (!(std::abs(volume) > 1e-12 * extent * extent * extent)) {
    throw error(fmt::format("mesh file '{}' encloses no volume", mesh_path));
  }
  if (volume < 0) {
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  }
  return mesh;
}

}  // namespace sluice
