// The viscosity constraints of a constraint fluid (Bodin, Lacoursière & Servin 2012): each
// fluid particle's velocity, axis by axis, held to the kernel-weighted mean of its fluid
// neighbours', v_i - sum_j w_ij v_j = 0 with w_ij = W_ij / sum_k W_ik, as a compliant
// velocity-level constraint: its impulse is the drag of a dashpot of rate beta on the
// particle's velocity relative to that mean, met implicitly (compliance 1 / (h m beta)), so
// that it damps any rate of relative motion stably. beta = 2 (D + 2) nu / h_k^2 gives the
// damping a fluid of kinematic viscosity nu puts on a velocity that varies over the kernel's
// length h_k (the SPH Laplacian's factor). Walls are free-slip for them: only fluid
// neighbours count.
#pragma once

#include <cstdint>
#include <vector>

#include "sluice/ccp/constraint_group.hpp"
#include "sluice/fluid/constraint/viscosity_rows.hpp"

namespace sluice {

class ViscosityConstraints final : public ConstraintGroup {
 public:
  using Entry = ViscosityEntry;

  // Rows for `particles` fluid particles (bodies of the problem placed by place(), each of
  // inverse mass `inverse_mass`) along the world axes in `axes` (2D: x and z).
  void begin(std::size_t particles, Real inverse_mass, std::vector<int> axes);
  // Particle i's neighbours with their kernel values (not yet normalised), in order.
  std::vector<Entry>& entries() { return entries_; }
  std::vector<std::size_t>& offsets() { return offsets_; }
  // Turns the kernel values into the weights w_ij and w_ji.
  void normalise();
  // Each row's compliance (the same for all) and warm start (particle-major, axis-minor).
  void set_compliance(Real compliance) { compliance_ = compliance; }
  std::vector<Real>& impulse() { return impulse_; }
  const std::vector<Real>& impulse() const { return impulse_; }

  // The problem's body of the first fluid particle (the bodies before it are rigid).
  void place(std::size_t first) { first_ = first; }

  std::size_t size() const override { return particles_ * axes_.size(); }
  void row_velocities(const BodyVelocities& u, std::span<Real> out) const override;
  void add_compliance(std::span<const Real> gamma, std::span<Real> out) const override;
  void apply_impulses(const CcpBodies& bodies, std::span<const Real> gamma,
                      BodyVelocities& u) const override;
  void project(std::span<Real>) const override {}
  void diagonal(const CcpBodies& bodies, std::span<Real> out) const override;
  void warm_start(std::span<Real> gamma) const override;
  void store(std::span<const Real> gamma) override;

  // The rows as plain arrays (viscosity_rows.hpp), for a device's copy.
  std::size_t entry_count() const { return entries_.size(); }
  ViscosityRows rows() const {
    ViscosityRows r{first_,          inverse_mass_, compliance_, offsets_.data(),
                    entries_.data(), {0, 0, 0},     axes_.size()};
    for (std::size_t a = 0; a < axes_.size(); ++a) r.axes[a] = axes_[a];
    return r;
  }

 private:
  std::size_t first_ = 0, particles_ = 0;
  Real inverse_mass_ = 0, compliance_ = 0;
  std::vector<int> axes_;
  std::vector<std::size_t> offsets_{0};
  std::vector<Entry> entries_;
  std::vector<Real> impulse_;
};

}  // namespace sluice
