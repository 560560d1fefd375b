#include "sluice/ccp/row_group.hpp"

#include <algorithm>
#include <cmath>

#include "sluice/ccp/cone.hpp"
#include "sluice/exec/policy.hpp"

namespace sluice {

namespace {

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
  for (const RowBlock& block : blocks_) {
    if (block.cone) out.emplace_back(block.key, block.first);
  }
  return out;
}

Real RowGroup::correct_slip(const BodyVelocities& u) {
  auto velocity = [&](const ConstraintRow& r) {
    return row_velocity(r, u.linear.data(), u.angular.data());
  };
  Real largest = 0;
  for (RowBlock& block : blocks_) {
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
  const CcpBodiesView view = bodies.view();
  std::vector<ConstraintRow> rows;
  std::vector<RowBlock> blocks;
  for (const RowBlock& block : blocks_) {
    const ConstraintRow& r = rows_[block.first];
    const Real d = inverse_mass_along(view, r.a, r.linear_a, r.angular_a) +
                   inverse_mass_along(view, r.b, r.linear_b, r.angular_b);
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
  const RowVelocity velocity{rows_.data(), u.linear.data(), u.angular.data(), out.data()};
  for (std::size_t k = 0; k < size(); ++k) velocity(k);
}

void RowGroup::apply_impulses(const CcpBodies& bodies, std::span<const Real> gamma,
                              BodyVelocities& u) const {
  RowImpulses{
      rows_.data(), size(), bodies.view(), gamma.data(), u.linear.data(), u.angular.data()}(0);
}

void RowGroup::project(std::span<Real> gamma) const {
  exec::Default::for_each_light(blocks_.size(),
                                RowProjection{rows_.data(), blocks_.data(), gamma.data()});
}

void RowGroup::diagonal(const CcpBodies& bodies, std::span<Real> out) const {
  exec::Default::for_each_light(
      blocks_.size(), RowDiagonal{rows_.data(), blocks_.data(), bodies.view(), out.data()});
}

void RowGroup::warm_start(std::span<Real> gamma) const {
  for (std::size_t k = 0; k < rows_.size(); ++k) gamma[k] = rows_[k].impulse;
}

void RowGroup::store(std::span<const Real> gamma) {
  for (std::size_t k = 0; k < rows_.size(); ++k) rows_[k].impulse = gamma[k];
}

}  // namespace sluice
