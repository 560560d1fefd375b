#include "sluice/fluid/constraint/viscosity_constraints.hpp"

#include <algorithm>

#include "sluice/ccp/ccp_steps.hpp"
#include "sluice/exec/policy.hpp"

namespace sluice {

void ViscosityConstraints::begin(std::size_t particles, Real inverse_mass, std::vector<int> axes) {
  particles_ = particles;
  inverse_mass_ = inverse_mass;
  axes_ = std::move(axes);
  offsets_.assign(particles + 1, 0);
  entries_.clear();
  impulse_.assign(size(), 0);
}

void ViscosityConstraints::normalise() {
  std::vector<Real> total(particles_, 0);
  exec::Default::for_each(particles_,
                          ViscosityKernelSum{offsets_.data(), entries_.data(), total.data()});
  exec::Default::for_each(particles_,
                          ViscosityWeights{offsets_.data(), entries_.data(), total.data()});
}

void ViscosityConstraints::row_velocities(const BodyVelocities& u, std::span<Real> out) const {
  exec::Default::for_each(particles_, ViscosityRowVelocities{rows(), u.linear.data(), out.data()});
}

void ViscosityConstraints::add_compliance(std::span<const Real> gamma, std::span<Real> out) const {
  exec::Default::for_each_light(
      size(), ccp_steps::AddUniformCompliance{compliance_, gamma.data(), out.data()});
}

void ViscosityConstraints::apply_impulses(const CcpBodies&, std::span<const Real> gamma,
                                          BodyVelocities& u) const {
  if (axes_.size() == 3) {
    return exec::Default::for_each(particles_,
                                   ViscosityImpulses<3>{rows(), gamma.data(), u.linear.data()});
  }
  exec::Default::for_each(particles_, ViscosityImpulses<2>{rows(), gamma.data(), u.linear.data()});
}

void ViscosityConstraints::diagonal(const CcpBodies&, std::span<Real> out) const {
  exec::Default::for_each(particles_, ViscosityDiagonal{rows(), out.data()});
}

void ViscosityConstraints::warm_start(std::span<Real> gamma) const {
  std::copy(impulse_.begin(), impulse_.end(), gamma.begin());
}

void ViscosityConstraints::store(std::span<const Real> gamma) {
  std::copy(gamma.begin(), gamma.end(), impulse_.begin());
}

}  // namespace sluice
