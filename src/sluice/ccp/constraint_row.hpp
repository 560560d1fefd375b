// A velocity-level constraint on the bodies: one row of a Jacobian, J (v, w) = bias, on one
// body or between two, whose impulse lambda is held within [lower, upper]: an equality
// (-inf, inf), a non-penetration (0, inf: J (v, w) >= bias, with lambda > 0 only where it is
// met with equality), or a bound. Joints, contacts and, in the monolithic coupling scheme, a
// fluid model contribute rows; three rows may also form a friction cone (row_group.hpp).
#pragma once

#include <cstddef>
#include <limits>

#include "sluice/core/state_archive.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

struct ConstraintRow {
  static constexpr std::size_t kWorld = std::numeric_limits<std::size_t>::max();
  std::size_t a = kWorld, b = kWorld;  // the bodies; kWorld for none
  Vec3 linear_a = Vec3::Zero(), angular_a = Vec3::Zero();
  Vec3 linear_b = Vec3::Zero(), angular_b = Vec3::Zero();
  double bias = 0;  // the velocity J (v, w) must reach
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  double impulse = 0;  // the solution: lambda [N s]
};

inline void archive_state(StateArchive& a, ConstraintRow& r) {
  a(r.a, r.b, r.linear_a, r.angular_a, r.linear_b, r.angular_b, r.bias, r.lower, r.upper,
    r.impulse);
}

}  // namespace sluice
