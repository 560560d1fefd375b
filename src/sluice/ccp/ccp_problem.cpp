#include "sluice/ccp/ccp_problem.hpp"

#include "sluice/exec/policy.hpp"

namespace sluice {

void CcpProblem::add(ConstraintGroup& group) {
  groups_.push_back(&group);
  offsets_.push_back(size_);
  size_ += group.size();
}

void CcpProblem::clear_groups() {
  groups_.clear();
  offsets_.clear();
  size_ = 0;
}

void CcpProblem::gradient(std::span<const Real> gamma, std::span<Real> g, BodyVelocities& u) const {
  u.linear = bodies.velocity;
  u.angular = bodies.angular_velocity;
  for (std::size_t k = 0; k < groups_.size(); ++k) {
    groups_[k]->apply_impulses(bodies, gamma.subspan(offsets_[k], groups_[k]->size()), u);
  }
  for (std::size_t k = 0; k < groups_.size(); ++k) {
    const std::span<Real> out = g.subspan(offsets_[k], groups_[k]->size());
    groups_[k]->row_velocities(u, out);
    groups_[k]->add_compliance(gamma.subspan(offsets_[k], groups_[k]->size()), out);
  }
}

void CcpProblem::project(std::span<Real> gamma) const {
  for (std::size_t k = 0; k < groups_.size(); ++k)
    groups_[k]->project(gamma.subspan(offsets_[k], groups_[k]->size()));
}

void CcpProblem::diagonal(std::span<Real> out) const {
  for (std::size_t k = 0; k < groups_.size(); ++k)
    groups_[k]->diagonal(bodies, out.subspan(offsets_[k], groups_[k]->size()));
}

void CcpProblem::warm_start(std::span<Real> gamma) const {
  for (std::size_t k = 0; k < groups_.size(); ++k)
    groups_[k]->warm_start(gamma.subspan(offsets_[k], groups_[k]->size()));
}

void CcpProblem::store(std::span<const Real> gamma) {
  for (std::size_t k = 0; k < groups_.size(); ++k)
    groups_[k]->store(gamma.subspan(offsets_[k], groups_[k]->size()));
}

}  // namespace sluice
