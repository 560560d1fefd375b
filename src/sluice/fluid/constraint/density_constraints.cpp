#include "sluice/fluid/constraint/density_constraints.hpp"

#include <algorithm>

#include "sluice/ccp/ccp_steps.hpp"
#include "sluice/exec/policy.hpp"

namespace sluice {

void DensityConstraints::begin(std::size_t fluid_rows, Real inverse_mass, bool unilateral) {
  fluid_rows_ = fluid_rows;
  inverse_mass_ = inverse_mass;
  unilateral_ = unilateral;
  offsets_.assign(1, 0);
  body_offsets_.assign(1, 0);
  entries_.clear();
  body_entries_.clear();
  sigma_.clear();
  c_.clear();
}

void DensityConstraints::append(const Block& block) {
  std::size_t e = 0, b = 0;
  for (std::size_t r = 0; r < block.c.size(); ++r) {
    const bool fluid = c_.size() < fluid_rows_;
    entries_.insert(entries_.end(), block.entries.begin() + std::ptrdiff_t(e),
                    block.entries.begin() + std::ptrdiff_t(e + block.entry_counts[r]));
    e += block.entry_counts[r];
    offsets_.push_back(entries_.size());
    body_entries_.insert(body_entries_.end(), block.bodies.begin() + std::ptrdiff_t(b),
                         block.bodies.begin() + std::ptrdiff_t(b + block.body_counts[r]));
    b += block.body_counts[r];
    body_offsets_.push_back(body_entries_.size());
    if (fluid) sigma_.push_back(block.sigma[r]);
    c_.push_back(block.c[r]);
  }
  target_.resize(c_.size(), 0);
  compliance_.resize(c_.size(), 0);
  impulse_.resize(c_.size(), 0);
}

void DensityConstraints::row_velocities(const BodyVelocities& u, std::span<Real> out) const {
  exec::Default::for_each(size(), DensityRowVelocities{rows(), u.linear.data(), u.angular.data(),
                                                       target_.data(), out.data()});
}

void DensityConstraints::add_compliance(std::span<const Real> gamma, std::span<Real> out) const {
  exec::Default::for_each_light(
      size(), ccp_steps::AddCompliance{compliance_.data(), gamma.data(), out.data()});
}

void DensityConstraints::apply_impulses(const CcpBodies& bodies, std::span<const Real> gamma,
                                        BodyVelocities& u) const {
  exec::Default::for_each(fluid_rows_, DensityFluidImpulses{rows(), gamma.data(), u.linear.data()});
  if (body_entries_.empty()) return;
  std::vector<Vec3> impulse(first_), moment(first_);
  DensityBodyImpulses{body_entries_.data(), body_entries_.size(), first_,
                      bodies.view(),        gamma.data(),         impulse.data(),
                      moment.data(),        u.linear.data(),      u.angular.data()}(0);
}

void DensityConstraints::project(std::span<Real> gamma) const {
  if (!unilateral_) return;
  exec::Default::for_each_light(size(), ccp_steps::NotNegative{gamma.data()});
}

void DensityConstraints::diagonal(const CcpBodies& bodies, std::span<Real> out) const {
  exec::Default::for_each(size(),
                          DensityDiagonal{rows(), bodies.view(), compliance_.data(), out.data()});
}

void DensityConstraints::warm_start(std::span<Real> gamma) const {
  std::copy(impulse_.begin(), impulse_.end(), gamma.begin());
}

void DensityConstraints::store(std::span<const Real> gamma) {
  std::copy(gamma.begin(), gamma.end(), impulse_.begin());
}

}  // namespace sluice
