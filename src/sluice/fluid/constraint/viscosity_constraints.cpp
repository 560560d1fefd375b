#include "sluice/fluid/constraint/viscosity_constraints.hpp"

#include <algorithm>

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
  exec::Default::for_each(particles_, [&](std::size_t i) {
    for (std::size_t k = offsets_[i]; k < offsets_[i + 1]; ++k) total[i] += entries_[k].forward;
  });
  exec::Default::for_each(particles_, [&](std::size_t i) {
    for (std::size_t k = offsets_[i]; k < offsets_[i + 1]; ++k) {
      Entry& e = entries_[k];
      const Real w = e.forward;
      e.forward = w / total[i];
      e.backward = w / total[e.particle];
    }
  });
}

void ViscosityConstraints::row_velocities(const BodyVelocities& u, std::span<Real> out) const {
  const std::size_t n = axes_.size();
  exec::Default::for_each(particles_, [&](std::size_t i) {
    Vec3 mean = Vec3::Zero();
    for (std::size_t k = offsets_[i]; k < offsets_[i + 1]; ++k)
      mean += entries_[k].forward * u.linear[first_ + entries_[k].particle];
    const Vec3 relative = u.linear[first_ + i] - mean;
    for (std::size_t a = 0; a < n; ++a) out[i * n + a] = relative[axes_[a]];
  });
}

void ViscosityConstraints::add_compliance(std::span<const Real> gamma, std::span<Real> out) const {
  exec::Default::for_each_light(size(), [&](std::size_t r) { out[r] += compliance_ * gamma[r]; });
}

void ViscosityConstraints::apply_impulses(const CcpBodies&, std::span<const Real> gamma,
                                          BodyVelocities& u) const {
  if (axes_.size() == 3) return apply_impulses_along<3>(gamma, u);
  apply_impulses_along<2>(gamma, u);
}

// With the number of axes known, each axis's sum is a local of its own, not a component of a
// vector picked at run time: no store to a variable place in every entry's update.
template <std::size_t N>
void ViscosityConstraints::apply_impulses_along(std::span<const Real> gamma,
                                                BodyVelocities& u) const {
  exec::Default::for_each(particles_, [&](std::size_t i) {
    Real p[N];
    for (std::size_t a = 0; a < N; ++a) p[a] = gamma[i * N + a];
    for (std::size_t k = offsets_[i]; k < offsets_[i + 1]; ++k) {
      const Entry& e = entries_[k];
      const Real* g = &gamma[e.particle * N];
      for (std::size_t a = 0; a < N; ++a) p[a] -= e.backward * g[a];
    }
    Vec3 impulse = Vec3::Zero();
    for (std::size_t a = 0; a < N; ++a) impulse[axes_[a]] = p[a];
    u.linear[first_ + i] += inverse_mass_ * impulse;
  });
}

void ViscosityConstraints::diagonal(const CcpBodies&, std::span<Real> out) const {
  const std::size_t n = axes_.size();
  exec::Default::for_each(particles_, [&](std::size_t i) {
    Real d = 1;
    for (std::size_t k = offsets_[i]; k < offsets_[i + 1]; ++k)
      d += entries_[k].forward * entries_[k].forward;
    for (std::size_t a = 0; a < n; ++a) out[i * n + a] = inverse_mass_ * d + compliance_;
  });
}

void ViscosityConstraints::warm_start(std::span<Real> gamma) const {
  std::copy(impulse_.begin(), impulse_.end(), gamma.begin());
}

void ViscosityConstraints::store(std::span<const Real> gamma) {
  std::copy(gamma.begin(), gamma.end(), impulse_.begin());
}

}  // namespace sluice
