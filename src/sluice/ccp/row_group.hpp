// Constraint rows with full Jacobians (ConstraintRow): joints, contacts of rigid bodies with
// their lever arms, a fluid's rows on the bodies. A row alone is held within its bounds; three
// rows (normal, then two tangents) may form a contact's friction cone. Meant for thousands of
// rows; a granular fluid's millions of sphere contacts have a group of their own.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "sluice/ccp/constraint_group.hpp"
#include "sluice/ccp/constraint_row.hpp"
#include "sluice/ccp/row_group_rows.hpp"

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
  // `key` names the contact for the next step's warm start (cones()).
  void add_cone(const ConstraintRow& normal, const ConstraintRow& u, const ConstraintRow& v,
                Real mu, Real cohesion, std::uint64_t key = 0);
  // Each cone's key and first row.
  std::vector<std::pair<std::uint64_t, std::size_t>> cones() const;
  // The cone complementarity relaxes Coulomb's law: a contact that slips at u_t separates at
  // mu |u_t| (Anitescu & Tasora 2010). This asks each cone's normal row for mu |u_t| more,
  // u_t its slip at the velocities u, which cancels that separation once the slip settles (a
  // fixed point of the exact law); returns the largest change of a row's target [m/s].
  Real correct_slip(const BodyVelocities& u);

  // Drops the rows (a cone: by its normal row) that cannot move any body: on fixed bodies or
  // locked degrees of freedom alone (a 2D case's rows out of its plane). Nothing would hold
  // their impulses back.
  void drop_inert(const CcpBodies& bodies);

  const std::vector<ConstraintRow>& rows() const { return rows_; }
  std::vector<ConstraintRow>& rows() { return rows_; }
  const std::vector<RowBlock>& blocks() const { return blocks_; }

  std::size_t size() const override { return rows_.size(); }
  void row_velocities(const BodyVelocities& u, std::span<Real> out) const override;
  void apply_impulses(const CcpBodies& bodies, std::span<const Real> gamma,
                      BodyVelocities& u) const override;
  void project(std::span<Real> gamma) const override;
  void diagonal(const CcpBodies& bodies, std::span<Real> out) const override;
  void warm_start(std::span<Real> gamma) const override;
  void store(std::span<const Real> gamma) override;

  void archive_state(StateArchive& a) {
    a(rows_);
    a(blocks_);
  }

 private:
  std::vector<ConstraintRow> rows_;
  std::vector<RowBlock> blocks_;
};

}  // namespace sluice
