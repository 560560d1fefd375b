// The three rows of a frictional contact between two bodies, for a friction cone
// (row_group.hpp's add_cone): along the contact normal, from body a towards body b, and along
// two tangents (cone.hpp's tangent_basis), each acting at the contact point through the arms
// from the bodies' centres of mass. Body-body contacts (contact/contact_pipeline.cpp) and a
// granular fluid's sphere-body contacts build their cones here.
#pragma once

#include <array>
#include <cstddef>

#include "sluice/ccp/cone.hpp"
#include "sluice/ccp/constraint_row.hpp"

namespace sluice {

// Rows 0 (normal), 1 and 2 (tangents), with no bias, bounds or impulse yet.
inline std::array<ConstraintRow, 3> contact_rows(std::size_t a, std::size_t b, const Vec3& normal,
                                                 const Vec3& arm_a, const Vec3& arm_b) {
  Vec3 axes[3];
  axes[0] = normal;
  tangent_basis(normal, axes[1], axes[2]);
  std::array<ConstraintRow, 3> rows;
  for (int k = 0; k < 3; ++k) {
    rows[k].a = a;
    rows[k].b = b;
    rows[k].linear_a = -axes[k];
    rows[k].angular_a = -arm_a.cross(axes[k]);
    rows[k].linear_b = axes[k];
    rows[k].angular_b = arm_b.cross(axes[k]);
  }
  return rows;
}

}  // namespace sluice
