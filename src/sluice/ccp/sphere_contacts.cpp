#include "sluice/ccp/sphere_contacts.hpp"

#include <algorithm>

#include "sluice/ccp/cone.hpp"
#include "sluice/exec/policy.hpp"

namespace sluice {

void SphereContacts::begin(std::size_t first, std::size_t count, std::size_t identities,
                           Real friction, Real cohesion, Real rolling_friction) {
  remember();
  first_ = first;
  count_ = count;
  identities_ = identities;
  friction_ = friction;
  cohesion_ = cohesion;
  rolling_friction_ = friction > 0 ? rolling_friction : 0;
  contacts_.clear();
}

void SphereContacts::remember() {
  const std::size_t k = rows_per_contact();
  if (impulse_.size() != contacts_.size() * k || identities_ == 0) {
    memory_ = {};
    return;
  }
  Memory& m = memory_;
  m.offsets.assign(identities_ + 1, 0);
  for (const Contact& c : contacts_) ++m.offsets[c.owner + 1];
  for (std::size_t id = 0; id < identities_; ++id) m.offsets[id + 1] += m.offsets[id];
  m.partner.resize(contacts_.size());
  m.impulse.resize(contacts_.size() * k);
  std::vector<std::uint32_t> next(m.offsets.begin(), m.offsets.end() - 1);
  for (std::size_t c = 0; c < contacts_.size(); ++c) {
    const std::uint32_t slot = next[contacts_[c].owner]++;
    m.partner[slot] = contacts_[c].partner;
    for (std::size_t r = 0; r < k; ++r) m.impulse[slot * k + r] = impulse_[c * k + r];
  }
}

void SphereContacts::finish() {
  const std::size_t n = contacts_.size(), k = rows_per_contact();
  // The tangents of every contact with friction, once: each iteration of the solve reads them
  // three times a contact.
  tangents_.resize(k >= 3 ? 2 * n : 0);
  if (k >= 3) {
    exec::Default::for_each_light(n, [&](std::size_t c) {
      tangent_basis(contacts_[c].normal, tangents_[2 * c], tangents_[2 * c + 1]);
    });
  }
  // Each sphere's contacts, in contact order.
  list_offsets_.assign(count_ + 1, 0);
  for (const Contact& c : contacts_) {
    if (c.a != kWorld) ++list_offsets_[c.a - first_ + 1];
    ++list_offsets_[c.b - first_ + 1];
  }
  for (std::size_t s = 0; s < count_; ++s) list_offsets_[s + 1] += list_offsets_[s];
  list_.resize(list_offsets_.back());
  std::vector<std::uint32_t> next(list_offsets_.begin(), list_offsets_.end() - 1);
  for (std::size_t c = 0; c < n; ++c) {
    const Contact& contact = contacts_[c];
    const Vec3& m = contact.normal;
    if (contact.a != kWorld) {
      list_[next[contact.a - first_]++] = {{float(-m.x()), float(-m.y()), float(-m.z())},
                                           std::uint32_t(2 * c)};
    }
    list_[next[contact.b - first_]++] = {{float(m.x()), float(m.y()), float(m.z())},
                                         std::uint32_t(2 * c + 1)};
  }
  // Warm start: the same owner and partner as a contact of the last step.
  impulse_.assign(n * k, 0);
  const Memory& m = memory_;
  if (m.offsets.size() != identities_ + 1) return;
  exec::Default::for_each_light(n, [&](std::size_t c) {
    const Contact& contact = contacts_[c];
    for (std::uint32_t slot = m.offsets[contact.owner]; slot < m.offsets[contact.owner + 1];
         ++slot) {
      if (m.partner[slot] != contact.partner) continue;
      for (std::size_t r = 0; r < k; ++r) impulse_[c * k + r] = m.impulse[slot * k + r];
      return;
    }
  });
}

void SphereContacts::row_velocities(const BodyVelocities& u, std::span<Real> out) const {
  exec::Default::for_each_light(
      contacts_.size(), SphereRowVelocities{rows(), u.linear.data(), u.angular.data(), out.data()});
}

void SphereContacts::apply_impulses(const CcpBodies& bodies, std::span<const Real> gamma,
                                    BodyVelocities& u) const {
  if (rows_per_contact() == 1) {
    exec::Default::for_each_light(
        count_, SphereNormalImpulses{list_offsets_.data(), list_.data(), gamma.data(), first_,
                                     bodies.view(), u.linear.data()});
    return;
  }
  exec::Default::for_each_light(
      count_, SphereImpulses{rows(), list_offsets_.data(), list_.data(), gamma.data(), first_,
                             bodies.view(), u.linear.data(), u.angular.data()});
}

void SphereContacts::project(std::span<Real> gamma) const {
  exec::Default::for_each_light(
      contacts_.size(),
      SphereProjection{rows(), friction_, cohesion_, rolling_friction_, gamma.data()});
}

void SphereContacts::diagonal(const CcpBodies& bodies, std::span<Real> out) const {
  exec::Default::for_each_light(contacts_.size(),
                                SphereDiagonal{rows(), bodies.view(), out.data()});
}

void SphereContacts::warm_start(std::span<Real> gamma) const {
  std::copy(impulse_.begin(), impulse_.end(), gamma.begin());
}

void SphereContacts::store(std::span<const Real> gamma) {
  impulse_.assign(gamma.begin(), gamma.end());
}

}  // namespace sluice
