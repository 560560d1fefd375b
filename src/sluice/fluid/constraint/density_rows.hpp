// The density constraints' rows (density_constraints.hpp) as loop bodies over plain arrays, each
// a function of one row's or one fluid particle's index, so that the host's threads run them on
// the group's vectors and a device run on its copy: the rows' velocities, each fluid particle's
// gathered impulses, the diagonal. (The rigid bodies' share of the impulses is summed per body
// apart: few bodies, many rows.)
#pragma once

#include <cstddef>
#include <cstdint>

#include "sluice/ccp/ccp_bodies.hpp"
#include "sluice/core/host_device.hpp"

namespace sluice {

// A neighbour k of a row: its row (fluid rows: its problem body is first + row), and q_rk.
struct DensityEntry {
  std::uint32_t row;
  Vec3 q;
};
// A row's Jacobian on a rigid body of the problem (its velocity and angular velocity).
struct DensityBodyEntry {
  std::uint32_t row;
  std::uint32_t body;
  Vec3 linear, angular;
};

// The rows: [0, fluid_rows) the fluid particles' (row j acts on the problem's body first + j),
// then the walls' and bodies'; each row's entries and body entries from its offsets.
struct DensityRows {
  std::size_t first, fluid_rows;
  Real inverse_mass;
  const std::size_t* offsets;
  const DensityEntry* entries;
  const std::size_t* body_offsets;
  const DensityBodyEntry* body_entries;
  const Vec3* sigma;  // of the fluid rows
};

// out[r] = J_r u - target_r.
struct DensityRowVelocities {
  DensityRows rows;
  const Vec3* linear;
  const Vec3* angular;
  const Real* target;
  Real* out;
  SLUICE_HOST_DEVICE void operator()(std::size_t r) const {
    Real v = 0;
    if (r < rows.fluid_rows) v -= rows.sigma[r].dot(linear[rows.first + r]);
    for (std::size_t k = rows.offsets[r]; k < rows.offsets[r + 1]; ++k) {
      const DensityEntry& e = rows.entries[k];
      if (e.row < rows.fluid_rows) v += e.q.dot(linear[rows.first + e.row]);
    }
    for (std::size_t k = rows.body_offsets[r]; k < rows.body_offsets[r + 1]; ++k) {
      const DensityBodyEntry& e = rows.body_entries[k];
      v += e.linear.dot(linear[e.body]) + e.angular.dot(angular[e.body]);
    }
    out[r] = v - target[r];
  }
};

// Fluid particle j's velocity change: its own row's -sigma_j and, from each neighbour row k,
// -q_jk (= q_kj), gathered in its row's order.
struct DensityFluidImpulses {
  DensityRows rows;
  const Real* gamma;
  Vec3* linear;
  SLUICE_HOST_DEVICE void operator()(std::size_t j) const {
    Vec3 p = -gamma[j] * rows.sigma[j];
    for (std::size_t k = rows.offsets[j]; k < rows.offsets[j + 1]; ++k)
      p -= gamma[rows.entries[k].row] * rows.entries[k].q;
    linear[rows.first + j] += rows.inverse_mass * p;
  }
};

// The rows' impulses on the rigid bodies [0, count) from their body entries, summed per body in
// entry order into impulse and moment (count each), then taken through M^-1 (run as one index:
// a few bodies, entries from many rows).
struct DensityBodyImpulses {
  const DensityBodyEntry* entries;
  std::size_t entry_count, count;
  CcpBodiesView bodies;
  const Real* gamma;
  Vec3* impulse;
  Vec3* moment;
  Vec3* linear;
  Vec3* angular;
  SLUICE_HOST_DEVICE void operator()(std::size_t) const {
    for (std::size_t b = 0; b < count; ++b) impulse[b] = moment[b] = Vec3::Zero();
    for (std::size_t k = 0; k < entry_count; ++k) {
      const DensityBodyEntry& e = entries[k];
      impulse[e.body] += gamma[e.row] * e.linear;
      moment[e.body] += gamma[e.row] * e.angular;
    }
    for (std::size_t b = 0; b < count; ++b) {
      if (impulse[b].isZero() && moment[b].isZero()) continue;
      Vec3 dv, dw;
      bodies.velocity_change(b, impulse[b], moment[b], dv, dw);
      linear[b] += dv;
      angular[b] += dw;
    }
  }
};

// Row r's inverse effective mass plus its compliance: J_r M^-1 J_r^T + Sigma_r.
struct DensityDiagonal {
  DensityRows rows;
  CcpBodiesView bodies;
  const Real* compliance;
  Real* out;
  SLUICE_HOST_DEVICE void operator()(std::size_t r) const {
    Real d = r < rows.fluid_rows ? rows.sigma[r].squaredNorm() : 0;
    for (std::size_t k = rows.offsets[r]; k < rows.offsets[r + 1]; ++k) {
      if (rows.entries[k].row < rows.fluid_rows) d += rows.entries[k].q.squaredNorm();
    }
    d *= rows.inverse_mass;
    for (std::size_t k = rows.body_offsets[r]; k < rows.body_offsets[r + 1]; ++k) {
      const DensityBodyEntry& e = rows.body_entries[k];
      Vec3 dv, dw;
      bodies.velocity_change(e.body, e.linear, e.angular, dv, dw);
      d += e.linear.dot(dv) + e.angular.dot(dw);
    }
    out[r] = d + compliance[r];
  }
};

}  // namespace sluice
