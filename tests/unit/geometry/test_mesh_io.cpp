// Reading STL and OBJ meshes, closedness and volume checks, and the errors for bad mesh files.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "sluice/core/errors.hpp"
#include "sluice/geometry/mesh_io.hpp"
#include "support/scratch_dir.hpp"

namespace sluice {
namespace {

namespace fs = std::filesystem;
using Triangle = std::array<Vec3, 3>;

// The unit cube [0, 1]^3 as 12 separate outward-wound triangles (each with its own corners,
// as STL stores them).
std::vector<Triangle> cube_triangles() {
  auto corner = [](int k) { return Vec3(k & 1 ? 1 : 0, k & 2 ? 1 : 0, k & 4 ? 1 : 0); };
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::vector<Triangle> out;
  for (const auto& q : quads) {
    out.push_back({corner(q[0]), corner(q[1]), corner(q[2])});
    out.push_back({corner(q[0]), corner(q[2]), corner(q[3])});
  }
  return out;
}

Vec3 facet_normal(const Triangle& t) {
  return (t[1] - t[0]).cross(t[2] - t[0]).normalized();
}

TriangleMesh tetrahedron() {
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

const std::string kCase = "case.yaml";
const std::string kKey = "bodies[0].mesh";

class MeshIo : public ::testing::Test {
 protected:
  std::string write_text(const std::string& name, const std::string& text) {
    const auto path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }

  std::string write_ascii_stl(const std::string& name, const std::vector<Triangle>& triangles) {
    std::string text = "solid cube\n";
    for (const auto& t : triangles) {
      const Vec3 n = facet_normal(t);
      text += "  facet normal " + std::to_string(n.x()) + " " + std::to_string(n.y()) + " " +
              std::to_string(n.z()) + "\n    outer loop\n";
      for (const Vec3& v : t) {
        text += "      vertex " + std::to_string(v.x()) + " " + std::to_string(v.y()) + " " +
                std::to_string(v.z()) + "\n";
      }
      text += "    endloop\n  endfacet\n";
    }
    text += "endsolid cube\n";
    return write_text(name, text);
  }

  // Binary STL: 80-byte header, uint32 count, then per facet 12 little-endian float32 (normal,
  // three corners) and a uint16 attribute. x86 is little-endian, so plain copies do.
  std::string write_binary_stl(const std::string& name, const std::vector<Triangle>& triangles) {
    std::string bytes(80, ' ');
    bytes.replace(0, 21, "binary cube for tests");
    auto put = [&bytes](const auto& value) {
      char raw[sizeof(value)];
      std::memcpy(raw, &value, sizeof(value));
      bytes.append(raw, sizeof(value));
    };
    put(static_cast<std::uint32_t>(triangles.size()));
    for (const auto& t : triangles) {
      const Vec3 n = facet_normal(t);
      for (int i = 0; i < 3; ++i) put(static_cast<float>(n[i]));
      for (const Vec3& v : t) {
        for (int i = 0; i < 3; ++i) put(static_cast<float>(v[i]));
      }
      put(std::uint16_t{0});
    }
    const auto path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }

  test_support::ScratchDir dir_{"sluice_mesh_io"};
};

TEST_F(MeshIo, AsciiStlCubeLoadsClosedWithSharedCorners) {
  const auto mesh = read_mesh(write_ascii_stl("cube.stl", cube_triangles()), 1.0, kCase, 12, kKey);
  EXPECT_EQ(mesh.vertices.size(), 8u);
  EXPECT_EQ(mesh.triangles.size(), 12u);
  EXPECT_TRUE(is_closed(mesh, nullptr));
  EXPECT_NEAR(signed_volume(mesh), 1.0, 1e-12);
}

TEST_F(MeshIo, BinaryStlCubeLoadsClosedAndScaled) {
  const auto path = write_binary_stl("cube_bin.stl", cube_triangles());
  ASSERT_EQ(fs::file_size(path), 84u + 12u * 50u);
  const auto mesh = read_mesh(path, 0.5, kCase, 12, kKey);
  EXPECT_EQ(mesh.vertices.size(), 8u);
  EXPECT_EQ(mesh.triangles.size(), 12u);
  EXPECT_TRUE(is_closed(mesh, nullptr));
  EXPECT_NEAR(signed_volume(mesh), 0.125, 1e-12);
  for (const Vec3& v : mesh.vertices) EXPECT_LE(v.maxCoeff(), 0.5);
}

TEST_F(MeshIo, ObjTetrahedronLoads) {
  const auto path = write_text("tet.obj",
                               "# unit corner tetrahedron\n"
                               "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                               "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const auto mesh = read_mesh(path, 2.0, kCase, 12, kKey);
  EXPECT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.triangles.size(), 4u);
  EXPECT_TRUE(is_closed(mesh, nullptr));
  EXPECT_NEAR(signed_volume(mesh), 8.0 / 6.0, 1e-12);
}

TEST_F(MeshIo, InwardWoundMeshIsFlipped) {
  const auto path = write_text("tet_inward.obj",
                               "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                               "f 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n");
  const auto mesh = read_mesh(path, 1.0, kCase, 12, kKey);
  EXPECT_TRUE(is_closed(mesh, nullptr));
  EXPECT_NEAR(signed_volume(mesh), 1.0 / 6.0, 1e-12);
}

// Quads are triangulated, and faces split over two objects (two Assimp meshes, each with its
// own vertex copies) still share their edges.
TEST_F(MeshIo, ObjQuadCubeInTwoObjectsIsWelded) {
  const auto path = write_text("cube.obj",
                               "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                               "v 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
                               "o lower\nf 1 3 4 2\nf 1 2 6 5\nf 1 5 7 3\n"
                               "o upper\nf 5 6 8 7\nf 3 7 8 4\nf 2 4 8 6\n");
  const auto mesh = read_mesh(path, 1.0, kCase, 12, kKey);
  EXPECT_EQ(mesh.vertices.size(), 8u);
  EXPECT_EQ(mesh.triangles.size(), 12u);
  EXPECT_NEAR(signed_volume(mesh), 1.0, 1e-12);
}

TEST_F(MeshIo, OpenBoxIsRejectedNamingFileAndEdge) {
  auto triangles = cube_triangles();
  triangles.resize(10);  // drop the last face (x = 1)
  const auto path = write_ascii_stl("open_box.stl", triangles);
  try {
    read_mesh(path, 1.0, kCase, 12, kKey);
    FAIL() << "open box accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("case.yaml:12: key 'bodies[0].mesh'"), std::string::npos) << what;
    EXPECT_NE(what.find(path), std::string::npos) << what;
    EXPECT_NE(what.find("not closed"), std::string::npos) << what;
    EXPECT_NE(what.find("is used by 1 triangle"), std::string::npos) << what;
    EXPECT_EQ(e.line(), 12);
    EXPECT_EQ(e.key(), kKey);
  }
}

TEST_F(MeshIo, MissingFileIsAnInputError) {
  const auto path = (dir_ / "nowhere.stl").string();
  try {
    read_mesh(path, 1.0, kCase, 7, kKey);
    FAIL() << "missing file accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("case.yaml:7: key 'bodies[0].mesh'"), std::string::npos) << what;
    EXPECT_NE(what.find(path), std::string::npos) << what;
    EXPECT_NE(what.find("cannot read"), std::string::npos) << what;
    EXPECT_NE(what.find("missing"), std::string::npos) << what;
  }
}

TEST_F(MeshIo, EmptyOrGarbageFileIsAnInputError) {
  for (const auto& [name, text] : {std::pair<std::string, std::string>{"empty.stl", ""},
                                   {"garbage.stl", "this is not a mesh\n"},
                                   {"no_faces.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n"}}) {
    const auto path = write_text(name, text);
    try {
      read_mesh(path, 1.0, kCase, 3, kKey);
      ADD_FAILURE() << name << " accepted";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("case.yaml:3: key 'bodies[0].mesh'"), std::string::npos) << what;
      EXPECT_NE(what.find(path), std::string::npos) << what;
    }
  }
}

TEST_F(MeshIo, BadScaleIsAnInputError) {
  const auto path = write_ascii_stl("cube.stl", cube_triangles());
  EXPECT_THROW(read_mesh(path, 0.0, kCase, 12, kKey), InputError);
  EXPECT_THROW(read_mesh(path, -1.0, kCase, 12, kKey), InputError);
}

TEST(MeshChecks, ClosedTetrahedronAndItsVolume) {
  std::string why;
  EXPECT_TRUE(is_closed(tetrahedron(), &why)) << why;
  EXPECT_NEAR(signed_volume(tetrahedron()), 1.0 / 6.0, 1e-15);
}

TEST(MeshChecks, ReportsWhyAMeshIsNotClosed) {
  std::string why;
  EXPECT_FALSE(is_closed(TriangleMesh{}, &why));
  EXPECT_NE(why.find("no triangles"), std::string::npos) << why;

  auto flipped = tetrahedron();
  std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
  EXPECT_FALSE(is_closed(flipped, &why));
  EXPECT_NE(why.find("triangles around edge (0, 1) disagree in orientation"), std::string::npos)
      << why;

  auto fin = tetrahedron();
  fin.vertices.emplace_back(0.5, -1, 0);
  fin.triangles.push_back({0, 1, 4});
  EXPECT_FALSE(is_closed(fin, &why));
  EXPECT_NE(why.find("edge (0, 1) is used by 3 triangles"), std::string::npos) << why;

  auto open = tetrahedron();
  open.triangles.pop_back();
  EXPECT_FALSE(is_closed(open, &why));
  EXPECT_NE(why.find("edge (1, 2) is used by 1 triangle"), std::string::npos) << why;
  EXPECT_NE(why.find("3 edges in all"), std::string::npos) << why;

  auto bad_index = tetrahedron();
  bad_index.triangles[0][0] = 9;
  EXPECT_FALSE(is_closed(bad_index, &why));
  EXPECT_NE(why.find("vertex 9"), std::string::npos) << why;
}

TEST(MeshChecks, InsideOutMeshHasNegativeVolume) {
  auto m = tetrahedron();
  for (auto& t : m.triangles) std::swap(t[1], t[2]);
  EXPECT_TRUE(is_closed(m, nullptr));
  EXPECT_NEAR(signed_volume(m), -1.0 / 6.0, 1e-15);
}

}  // namespace
}  // namespace sluice
