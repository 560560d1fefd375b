// A triangle surface: shared vertices and triangles as index triples, wound counter-clockwise
// seen from outside (so (b - a) x (c - a) points outward).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "sluice/core/types.hpp"

namespace sluice {

struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

}  // namespace sluice
