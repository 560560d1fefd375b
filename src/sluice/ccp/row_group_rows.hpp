// A row group's rows (row_group.hpp) as loop bodies over plain arrays, so that the host runs them
// on the group's vectors and a device run on its copy: each row's velocity, each block's
// projection and diagonal (a block: one row within its bounds, or a contact's cone of three),
// and the impulses onto the bodies, row after row on one thread (two rows may share a body; a
// group holds thousands of rows at most).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "sluice/ccp/ccp_bodies.hpp"
#include "sluice/ccp/cone.hpp"
#include "sluice/ccp/constraint_row.hpp"
#include "sluice/core/host_device.hpp"

namespace sluice {

// A block of a row group: its first row; a cone of three rows (normal, two tangents) with its
// friction and cohesion, or one row within its bounds; the key of its contact for the next
// step's warm start and the slip correction in its normal row's bias (RowGroup::correct_slip).
struct RowBlock {
  std::size_t first = 0;
  bool cone = false;
  Real friction = 0, cohesion = 0;
  std::uint64_t key = 0;
  Real slip_correction = 0;
};

inline void archive_state(StateArchive& a, RowBlock& b) {
  a(b.first, b.cone, b.friction, b.cohesion, b.key, b.slip_correction);
}

// J M^-1 J^T of one body's part of a row (zero for the world and fixed bodies).
SLUICE_HOST_DEVICE inline Real inverse_mass_along(const CcpBodiesView& bodies, std::size_t b,
                                                  const Vec3& linear, const Vec3& angular) {
  if (b == ConstraintRow::kWorld) return 0;
  Vec3 dv, dw;
  bodies.velocity_change(b, linear, angular, dv, dw);
  return linear.dot(dv) + angular.dot(dw);
}

// J (v, w) of row r for the body velocities (linear, angular).
SLUICE_HOST_DEVICE inline Real row_velocity(const ConstraintRow& r, const Vec3* linear,
                                            const Vec3* angular) {
  Real velocity = 0;
  if (r.a != ConstraintRow::kWorld)
    velocity += r.linear_a.dot(linear[r.a]) + r.angular_a.dot(angular[r.a]);
  if (r.b != ConstraintRow::kWorld)
    velocity += r.linear_b.dot(linear[r.b]) + r.angular_b.dot(angular[r.b]);
  return velocity;
}

// Row k's velocity less its bias.
struct RowVelocity {
  const ConstraintRow* rows;
  const Vec3* linear;
  const Vec3* angular;
  Real* out;
  SLUICE_HOST_DEVICE void operator()(std::size_t k) const {
    out[k] = row_velocity(rows[k], linear, angular) - rows[k].bias;
  }
};

// Every row's impulse gamma onto its bodies, in row order (run as one index).
struct RowImpulses {
  const ConstraintRow* rows;
  std::size_t count;
  CcpBodiesView bodies;
  const Real* gamma;
  Vec3* linear;
  Vec3* angular;
  SLUICE_HOST_DEVICE void operator()(std::size_t) const {
    for (std::size_t k = 0; k < count; ++k) {
      const ConstraintRow& r = rows[k];
      add(r.a, r.linear_a, r.angular_a, gamma[k]);
      add(r.b, r.linear_b, r.angular_b, gamma[k]);
    }
  }
  SLUICE_HOST_DEVICE void add(std::size_t b, const Vec3& l, const Vec3& a, Real g) const {
    if (b == ConstraintRow::kWorld || g == 0) return;
    Vec3 dv, dw;
    bodies.velocity_change(b, g * l, g * a, dv, dw);
    linear[b] += dv;
    angular[b] += dw;
  }
};

// Block k's impulses onto its cone or within its row's bounds.
struct RowProjection {
  const ConstraintRow* rows;
  const RowBlock* blocks;
  Real* gamma;
  SLUICE_HOST_DEVICE void operator()(std::size_t b) const {
    const RowBlock& block = blocks[b];
    const std::size_t k = block.first;
    if (block.cone) {
      project_on_cone(gamma[k], gamma[k + 1], gamma[k + 2], block.friction, block.cohesion);
    } else {
      gamma[k] = std::clamp(gamma[k], rows[k].lower, rows[k].upper);
    }
  }
};

// Block k's rows' share of the diagonal: its first row's J M^-1 J^T (a cone's three rows take
// the normal row's, so that a scaled step keeps the cone's shape).
struct RowDiagonal {
  const ConstraintRow* rows;
  const RowBlock* blocks;
  CcpBodiesView bodies;
  Real* out;
  SLUICE_HOST_DEVICE void operator()(std::size_t b) const {
    const RowBlock& block = blocks[b];
    const ConstraintRow& r = rows[block.first];
    const Real d = inverse_mass_along(bodies, r.a, r.linear_a, r.angular_a) +
                   inverse_mass_along(bodies, r.b, r.linear_b, r.angular_b);
    const std::size_t n = block.cone ? 3 : 1;
    for (std::size_t k = 0; k < n; ++k) out[block.first + k] = d;
  }
};

}  // namespace sluice
