#include "sluice/ccp/row_group.hpp"

#include <algorithm>
#include <cmath>

#include "sluice/ccp/cone.hpp"

namespace sluice {

namespace {

// J M^-1 J^T of one body's part of a row (zero for the world and fixed bodies).
Real inverse_mass_along(const CcpBodies& bodies, std::size_t b, const Vec3& linear,
                        const Vec3& angular) {
  if (b == ConstraintRow::kWorld) return 0;
  Vec3 dv, dw;
  bodies.velocity_change(b, linear, angular, dv, dw);
  return linear.dot(dv) + angular.dot(dw);
}

void add_impulse(const CcpBodies& bodies, std::size_t b, const Vec3& linear, const Vec3& angular,
                 Real gamma, BodyVelocities& u) {
  if (b == ConstraintRow::kWorld || gamma == 0) return;
  Vec3 dv, dw;
  bodies.velocity_change(b, gamma * linear, gamma * angular, dv, dw);
  u.linear[b] += dv;
  u.angular[b] += dw;
}

// J M^-1 J^T of a row had none of its bodies' degrees of freedom been locked.
Real unlocked_inverse_mass(const CcpBodies& bodies, const ConstraintRow& r) {
  Real d = 0;
  auto part = [&](std::size_t b, const Vec3& linear, const Vec3& angular) {
    if (b == ConstraintRow::kWorld) return;
    d += bodies.inverse_mass[b] * linear.squaredNorm();
    d += b < bodies.tensor_count() ? angular.dot(bodies.inverse_inertia[b] * angular)
                                   : bodies.inverse_inertia_scalar[b] * angular.squaredNorm();
  };
  part(r.a, r.linear_a, r.angular_a);
  part(r.b, r.linear_b, r.angular_b);
  return d;
}

}  // namespace

void RowGroup::add_row(const ConstraintRow& row) {
  blocks_.push_back({rows_.size(), false, 0, 0, 0});
  rows_.push_back(row);
}

void RowGroup::add_cone(const ConstraintRow& normal, const ConstraintRow& u, const ConstraintRow& v,
                        Real mu, Real cohesion, std::uint64_t key) {
  blocks_.push_back({rows_.size(), true, mu, cohesion, key});
  rows_.push_back(normal);
  rows_.push_back(u);
  rows_.push_back(v);
}

std::vector<std::pair<std::uint64_t, std::size_t>> RowGroup::cones() const {
  std::vector<std::pair<std::uint64_t, std::size_t>> out;
  for (const Block& block : blocks_) {
    if (block.cone) out.emplace_back(block.key, block.first);
  }
  return out;
}

Real RowGroup::correct_slip(const BodyVelocities& u) {
  auto velocity = [&](const ConstraintRow& r) {
    Real v = 0;
    if (r.a != ConstraintRow::kWorld)
      v += r.linear_a.dot(u.linear[r.a]) + r.angular_a.dot(u.angular[r.a]);
    if (r.b != ConstraintRow::kWorld)
      v += r.linear_b.dot(u.linear[r.b]) + r.angular_b.dot(u.angular[r.b]);
    return v;
  };
  Real largest = 0;
  for (Block& block : blocks_) {
    if (!block.cone || block.friction <= 0) continue;
    const Real slip =
        std::hypot(velocity(rows_[block.first + 1]), velocity(rows_[block.first + 2]));
    const Real correction = block.friction * slip;
    rows_[block.first].bias += correction - block.slip_correction;
    largest = std::max(largest, std::abs(correction - block.slip_correction));
    block.slip_correction = correction;
  }
  return largest;
}

void RowGroup::drop_inert(const CcpBodies& bodies) {
  std::vector<ConstraintRow> rows;
  std::vector<Block> blocks;
  for (const Block& block : blocks_) {
    const ConstraintRow& r = rows_[block.first];
    const Real d = inverse_mass_along(bodies, r.a, r.linear_a, r.angular_a) +
                   inverse_mass_along(bodies, r.b, r.linear_b, r.angular_b);
    // Zero, or round-off of a locked direction.
    if (!(d > 1e-12 * unlocked_inverse_mass(bodies, r))) continue;
    blocks.push_back({rows.size(), block.cone, block.friction, block.cohesion, block.key});
    const std::size_t n = block.cone ? 3 : 1;
    for (std::size_t k = 0; k < n; ++k) rows.push_back(rows_[block.first + k]);
  }
  rows_.swap(rows);
  blocks_.swap(blocks);
}

void RowGroup::row_velocities(const BodyVelocities& u, std::span<Real> out) const {
  for (std::size_t k = 0; k < rows_.size(); ++k) {
    const ConstraintRow& r = rows_[k];
    Real velocity = 0;
    if (r.a != ConstraintRow::kWorld)
      velocity += r.linear_a.dot(u.linear[r.a]) + r.angular_a.dot(u.angular[r.a]);
    if (r.b != ConstraintRow::kWorld)
      velocity += r.linear_b.dot(u.linear[r.b]) + r.angular_b.dot(u.angular[r.b]);
    out[k] = velocity - r.bias;
  }
}

void RowGroup::apply_impulses(const CcpBodies& bodies, std::span<const Real> gamma,
                              BodyVelocities& u) const {
  for (std::size_t k = 0; k < rows_.size(); ++k) {
    const ConstraintRow& r = rows_[k];
    add_impulse(bodies, r.a, r.linear_a, r.angular_a, gamma[k], u);
    add_impulse(bodies, r.b, r.linear_b, r.angular_b, gamma[k], u);
  }
}

void RowGroup::project(std::span<Real> gamma) const {
  for (const Block& block : blocks_) {
    const std::size_t k = block.first;
    if (block.cone) {
      project_on_cone(gamma[k], gamma[k + 1], gamma[k + 2], block.friction, block.cohesion);
    } else {
      gamma[k] = std::clamp(gamma[k], rows_[k].lower, rows_[k].upper);
    }
  }
}

void RowGroup::diagonal(const CcpBodies& bodies, std::span<Real> out) const {
  for (const Block& block : blocks_) {
    const ConstraintRow& r = rows_[block.first];
    const Real d = inverse_mass_along(bodies, r.a, r.linear_a, r.angular_a) +
                   inverse_mass_along(bodies, r.b, r.linear_b, r.angular_b);
    const std::size_t n = block.cone ? 3 : 1;
    for (std::size_t k = 0; k < n; ++k) out[block.first + k] = d;
  }
}

void RowGroup::warm_start(std::span<Real> gamma) const {
  for (std::size_t k = 0; k < rows_.size(); ++k) gamma[k] = rows_[k].impulse;
}

void RowGroup::store(std::span<const Real> gamma) {
  for (std::size_t k = 0; k < rows_.size(); ++k) rows_[k].impulse = gamma[k];
}

}  // namespace sluice
