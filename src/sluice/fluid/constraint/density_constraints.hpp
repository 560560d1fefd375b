// The density constraints of a constraint fluid (Bodin, Lacoursière & Servin 2012) as a group
// of the bodies' complementarity problem: one row per fluid particle, and one per wall
// particle, or particle of a body's outer layer, with fluid within its support (NearFluid).
// Row r asks that particle's kernel-summed density not exceed the rest density:
// c_r = dx (1 - rho_r / rho_ref) >= 0 (or = 0, bilateral), scaled by the spacing so that a
// row's velocity is in m/s like a contact's. Its Jacobian comes from the kernel gradient: with
// q_rk = dx (m / rho_ref) grad W(x_r - x_k),
//   fluid row j:        J v = -sigma_j . v_j + sum_k q_jk . v_k  (k: fluid or on a body),
//   wall or body row k: J v = sum_j q_kj . v_j - sigma_k . u_k    (j: fluid; u_k: the body's
//                                                                    velocity at k),
// sigma_r = sum_k q_rk over the row's neighbours. Each row is met in SPOOK's form
// (ccp/spook.hpp) with compliance Sigma_r. Every particle has the fluid's mass m, so
// q_kj = -q_jk and each fluid particle's velocity change is gathered from its own row's
// entries (no two threads write one particle, in a fixed order).
//
// Rows [0, fluid_rows) are the fluid particles, in particle order; fluid row j acts on the
// problem's body first + j. Rows after them are wall and body particles.
#pragma once

#include <cstdint>
#include <vector>

#include "sluice/ccp/constraint_group.hpp"
#include "sluice/fluid/constraint/density_rows.hpp"

namespace sluice {

class DensityConstraints final : public ConstraintGroup {
 public:
  using Entry = DensityEntry;
  using BodyEntry = DensityBodyEntry;

  // Empties the rows, for fluid rows acting on bodies (placed by place()) each of inverse mass
  // `inverse_mass`.
  void begin(std::size_t fluid_rows, Real inverse_mass, bool unilateral);
  // Consecutive rows, built apart (by one thread) and appended in order. A row: its
  // neighbours (entries of fluid rows act on its velocity; the others only receive the fluid
  // particle's reaction), sigma (fluid rows: on the particle itself), its Jacobian on bodies,
  // and its constraint value c.
  struct Block {
    std::vector<Entry> entries;
    std::vector<std::uint32_t> entry_counts;
    std::vector<BodyEntry> bodies;  // with the rows' numbers in the whole group
    std::vector<std::uint32_t> body_counts;
    std::vector<Vec3> sigma;
    std::vector<Real> c;
    void clear() {
      entries.clear();
      entry_counts.clear();
      bodies.clear();
      body_counts.clear();
      sigma.clear();
      c.clear();
    }
  };
  void append(const Block& block);

  // The SPOOK target and compliance of each row, for a step: set after the rows are added.
  std::vector<Real>& target() { return target_; }
  std::vector<Real>& compliance() { return compliance_; }
  // The impulses: the warm start (set before the solve) and, after it, the solution.
  std::vector<Real>& impulse() { return impulse_; }
  const std::vector<Real>& impulse() const { return impulse_; }
  Real constraint(std::size_t r) const { return c_[r]; }
  std::size_t fluid_rows() const { return fluid_rows_; }
  std::size_t entry_count() const { return entries_.size(); }
  const std::vector<BodyEntry>& body_entries() const { return body_entries_; }

  // The problem's body of the first fluid particle (the bodies before it are rigid).
  void place(std::size_t first) { first_ = first; }

  std::size_t size() const override { return c_.size(); }
  void row_velocities(const BodyVelocities& u, std::span<Real> out) const override;
  void add_compliance(std::span<const Real> gamma, std::span<Real> out) const override;
  void apply_impulses(const CcpBodies& bodies, std::span<const Real> gamma,
                      BodyVelocities& u) const override;
  void project(std::span<Real> gamma) const override;
  void diagonal(const CcpBodies& bodies, std::span<Real> out) const override;
  void warm_start(std::span<Real> gamma) const override;
  void store(std::span<const Real> gamma) override;

  // The rows as plain arrays (density_rows.hpp), for a device's copy; targets, compliance and
  // sign as set for the step.
  DensityRows rows() const {
    return {first_,          fluid_rows_,          inverse_mass_,        offsets_.data(),
            entries_.data(), body_offsets_.data(), body_entries_.data(), sigma_.data()};
  }
  const std::vector<Real>& target() const { return target_; }
  const std::vector<Real>& compliance() const { return compliance_; }
  bool unilateral() const { return unilateral_; }

 private:
  std::size_t first_ = 0, fluid_rows_ = 0;
  Real inverse_mass_ = 0;
  bool unilateral_ = true;
  std::vector<std::size_t> offsets_{0}, body_offsets_{0};  // each row's entries
  std::vector<Entry> entries_;
  std::vector<BodyEntry> body_entries_;
  std::vector<Vec3> sigma_;  // of the fluid rows
  std::vector<Real> c_, target_, compliance_, impulse_;
};

}  // namespace sluice
