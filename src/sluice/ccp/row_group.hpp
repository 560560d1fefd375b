// Constraint rows with full Jacobians (ConstraintRow): joints, contacts of rigid bodies with
// their lever arms, a fluid's rows on the bodies. A row alone is held within its bounds; three
// rows (normal, then two tangents) may form a contact's friction cone. Meant for thousands of
// rows; a granular fluid's millions of sphere contacts have a group of their own.
#pragma once

#include <vector>

#include "sluice/ccp/constraint_group.hpp"
#include "sluice/ccp/constraint_row.hpp"

namespace sluice {

class RowGroup final : public ConstraintGroup {
 public:
  void clear() {
    rows_.clear();
    blocks_.clear();
  }
  // A row held within its bounds.
  void add_row(const ConstraintRow& row);
  // A contact: its normal row (bias: the least normal velocity) and two tangent rows (bias 0),
  // their impulses in the cone of friction mu and cohesion c (an impulse the contact may pull
  // with; the rows' bounds are ignored).
  void add_cone(const ConstraintRow& normal, const ConstraintRow& u, const ConstraintRow& v,
                Real mu, Real cohesion);

  const std::vector<ConstraintRow>& rows() const { return rows_; }
  std::vector<ConstraintRow>& rows() { return rows_; }

  std::size_t size() const override { return rows_.size(); }
  void row_velocities(const BodyVelocities& u, std::span<Real> out) const override;
  void apply_impulses(const CcpBodies& bodies, std::span<const Real> gamma,
                      BodyVelocities& u) const override;
  void project(std::span<Real> gamma) const override;
  void diagonal(const CcpBodies& bodies, std::span<Real> out) const override;
  void warm_start(std::span<Real> gamma) const override;
  void store(std::span<const Real> gamma) override;

 private:
  struct Block {
    std::size_t first = 0;
    bool cone = false;
    Real friction = 0, cohesion = 0;
  };
  std::vector<ConstraintRow> rows_;
  std::vector<Block> blocks_;
};

}  // namespace sluice
