// The device copies (ccp/device_ccp_problem.hpp) of a constraint fluid's groups: its density
// rows (density_rows.hpp) and viscosity rows (viscosity_rows.hpp).
#pragma once

#include "sluice/ccp/ccp_steps.hpp"
#include "sluice/ccp/device_ccp_problem.hpp"
#include "sluice/fluid/constraint/density_constraints.hpp"
#include "sluice/fluid/constraint/viscosity_constraints.hpp"

namespace sluice {

template <class Backend>
class DeviceDensityConstraints final : public DeviceCcpGroup<Backend> {
 public:
  explicit DeviceDensityConstraints(const DensityConstraints& group)
      : host_(group.rows()), size_(group.size()), unilateral_(group.unilateral()) {
    exec::copy_to_array(offsets_, host_.offsets, size_ + 1);
    exec::copy_to_array(entries_, host_.entries, group.entry_count());
    exec::copy_to_array(body_offsets_, host_.body_offsets, size_ + 1);
    exec::copy_to_array(body_entries_, group.body_entries());
    exec::copy_to_array(sigma_, host_.sigma, host_.fluid_rows);
    exec::copy_to_array(target_, group.target());
    exec::copy_to_array(compliance_, group.compliance());
    impulse_.resize(host_.first);
    moment_.resize(host_.first);
  }
  void apply_impulses(const Real* gamma, DeviceCcpBodies<Backend>& b) override {
    Backend::for_each(host_.fluid_rows, DensityFluidImpulses{rows(), gamma, b.linear.data()});
    if (body_entries_.size() == 0) return;
    Backend::for_each(1, DensityBodyImpulses{body_entries_.data(), body_entries_.size(),
                                             host_.first, b.view(), gamma, impulse_.data(),
                                             moment_.data(), b.linear.data(), b.angular.data()});
  }
  void row_velocities(const Real* gamma, const DeviceCcpBodies<Backend>& b, Real* out) override {
    Backend::for_each(size_, DensityRowVelocities{rows(), b.linear.data(), b.angular.data(),
                                                  target_.data(), out});
    Backend::for_each(size_, ccp_steps::AddCompliance{compliance_.data(), gamma, out});
  }
  void project(Real* gamma) override {
    if (unilateral_) Backend::for_each(size_, ccp_steps::NotNegative{gamma});
  }
  void diagonal(const DeviceCcpBodies<Backend>& b, Real* out) override {
    Backend::for_each(size_, DensityDiagonal{rows(), b.view(), compliance_.data(), out});
  }
  std::size_t bytes() const override {
    return exec::bytes_of(offsets_) + exec::bytes_of(body_offsets_) + exec::bytes_of(entries_) +
           exec::bytes_of(body_entries_) + exec::bytes_of(sigma_) + exec::bytes_of(impulse_) +
           exec::bytes_of(moment_) + exec::bytes_of(target_) + exec::bytes_of(compliance_);
  }

 private:
  DensityRows rows() const {
    return {host_.first,     host_.fluid_rows,     host_.inverse_mass,   offsets_.data(),
            entries_.data(), body_offsets_.data(), body_entries_.data(), sigma_.data()};
  }

  DensityRows host_;  // the sizes and constants (its arrays are the host's)
  std::size_t size_;
  bool unilateral_;
  typename Backend::template Array<std::size_t> offsets_, body_offsets_;
  typename Backend::template Array<DensityEntry> entries_;
  typename Backend::template Array<DensityBodyEntry> body_entries_;
  typename Backend::template Array<Vec3> sigma_, impulse_, moment_;
  typename Backend::template Array<Real> target_, compliance_;
};

template <class Backend>
class DeviceViscosityConstraints final : public DeviceCcpGroup<Backend> {
 public:
  explicit DeviceViscosityConstraints(const ViscosityConstraints& group)
      : host_(group.rows()), particles_(group.size() / host_.axis_count) {
    exec::copy_to_array(offsets_, host_.offsets, particles_ + 1);
    exec::copy_to_array(entries_, host_.entries, group.entry_count());
  }
  void apply_impulses(const Real* gamma, DeviceCcpBodies<Backend>& b) override {
    if (host_.axis_count == 3) {
      Backend::for_each(particles_, ViscosityImpulses<3>{rows(), gamma, b.linear.data()});
    } else {
      Backend::for_each(particles_, ViscosityImpulses<2>{rows(), gamma, b.linear.data()});
    }
  }
  void row_velocities(const Real* gamma, const DeviceCcpBodies<Backend>& b, Real* out) override {
    Backend::for_each(particles_, ViscosityRowVelocities{rows(), b.linear.data(), out});
    Backend::for_each(particles_ * host_.axis_count,
                      ccp_steps::AddUniformCompliance{host_.compliance, gamma, out});
  }
  void project(Real*) override {}
  void diagonal(const DeviceCcpBodies<Backend>&, Real* out) override {
    Backend::for_each(particles_, ViscosityDiagonal{rows(), out});
  }
  std::size_t bytes() const override { return exec::bytes_of(offsets_) + exec::bytes_of(entries_); }

 private:
  ViscosityRows rows() const {
    ViscosityRows r = host_;
    r.offsets = offsets_.data();
    r.entries = entries_.data();
    return r;
  }

  ViscosityRows host_;  // the sizes and constants (its arrays are the host's)
  std::size_t particles_;
  typename Backend::template Array<std::size_t> offsets_;
  typename Backend::template Array<ViscosityEntry> entries_;
};

// Adds the copiers of the groups above to `device`.
template <class Backend>
void add_constraint_group_copiers(DeviceCcpProblem<Backend>& device) {
  add_copier_of<DensityConstraints, DeviceDensityConstraints<Backend>>(device);
  add_copier_of<ViscosityConstraints, DeviceViscosityConstraints<Backend>>(device);
}

}  // namespace sluice
