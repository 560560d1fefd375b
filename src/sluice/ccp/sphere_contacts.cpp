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
  const std::size_t k = rows_per_contact();
  exec::Default::for_each_light(contacts_.size(), [&](std::size_t c) {
    const Contact& contact = contacts_[c];
    const Vec3& n = contact.normal;
    Vec3 va = Vec3::Zero(), wa = Vec3::Zero();
    if (contact.a != kWorld) {
      va = u.linear[contact.a];
      wa = u.angular[contact.a];
    }
    const Vec3& vb = u.linear[contact.b];
    out[c * k] = n.dot(vb - va) - contact.target;
    if (k == 1) return;
    // The contact point's velocity on each side: v + w x (arm), arm_a = r_a n, arm_b = -r_b n.
    const Vec3 slip =
        vb - contact.radius_b * u.angular[contact.b].cross(n) - va - contact.radius_a * wa.cross(n);
    const Vec3& t1 = tangents_[2 * c];
    const Vec3& t2 = tangents_[2 * c + 1];
    out[c * k + 1] = t1.dot(slip);
    out[c * k + 2] = t2.dot(slip);
    if (k == 3) return;
    const Vec3 turn = u.angular[contact.b] - wa;
    out[c * k + 3] = t1.dot(turn);
    out[c * k + 4] = t2.dot(turn);
    out[c * k + 5] = n.dot(turn);
  });
}

void SphereContacts::apply_impulses(const CcpBodies& bodies, std::span<const Real> gamma,
                                    BodyVelocities& u) const {
  const std::size_t k = rows_per_contact();
  if (k == 1) {  // frictionless: the impulses along the normals alone
    exec::Default::for_each_light(count_, [&](std::size_t s) {
      Real px = 0, py = 0, pz = 0;
      for (std::uint32_t e = list_offsets_[s]; e < list_offsets_[s + 1]; ++e) {
        const Entry& entry = list_[e];
        const Real g = gamma[entry.contact_side / 2];
        px += g * entry.push[0];
        py += g * entry.push[1];
        pz += g * entry.push[2];
      }
      Vec3 dv, dw;
      bodies.velocity_change(first_ + s, Vec3(px, py, pz), Vec3::Zero(), dv, dw);
      u.linear[first_ + s] += dv;
    });
    return;
  }
  exec::Default::for_each_light(count_, [&](std::size_t s) {
    Vec3 p = Vec3::Zero(), l = Vec3::Zero();
    for (std::uint32_t e = list_offsets_[s]; e < list_offsets_[s + 1]; ++e) {
      const std::size_t c = list_[e].contact_side / 2;
      const bool is_b = list_[e].contact_side & 1;
      const Contact& contact = contacts_[c];
      const Vec3& n = contact.normal;
      Vec3 impulse = gamma[c * k] * n;  // on b; minus it on a
      if (k >= 3) {
        const Vec3& t1 = tangents_[2 * c];
        const Vec3& t2 = tangents_[2 * c + 1];
        const Vec3 tangential = gamma[c * k + 1] * t1 + gamma[c * k + 2] * t2;
        impulse += tangential;
        // arm x impulse: b's arm is -r_b n, a's is r_a n (and a takes minus the impulse).
        l += is_b ? Vec3(-contact.radius_b * n.cross(tangential))
                  : Vec3(-contact.radius_a * n.cross(tangential));
        if (k == 6) {
          const Vec3 torque = gamma[c * k + 3] * t1 + gamma[c * k + 4] * t2 + gamma[c * k + 5] * n;
          l += is_b ? torque : Vec3(-torque);
        }
      }
      p += is_b ? impulse : Vec3(-impulse);
    }
    Vec3 dv, dw;
    bodies.velocity_change(first_ + s, p, l, dv, dw);
    u.linear[first_ + s] += dv;
    u.angular[first_ + s] += dw;
  });
}

void SphereContacts::project(std::span<Real> gamma) const {
  const std::size_t k = rows_per_contact();
  exec::Default::for_each_light(contacts_.size(), [&](std::size_t c) {
    if (k == 1) {
      gamma[c] = std::max(gamma[c] + cohesion_, Real(0)) - cohesion_;
      return;
    }
    project_on_cone(gamma[c * k], gamma[c * k + 1], gamma[c * k + 2], friction_, cohesion_);
    if (k == 3) return;
    // Rolling and spinning torques within mu_r r n of the normal impulse just projected.
    const Contact& contact = contacts_[c];
    const Real r = contact.radius_a > 0
                       ? contact.radius_a * contact.radius_b / (contact.radius_a + contact.radius_b)
                       : contact.radius_b;
    const Real limit = rolling_friction_ * r * std::max<Real>(gamma[c * k] + cohesion_, 0);
    const Real rolling = std::hypot(gamma[c * k + 3], gamma[c * k + 4]);
    if (rolling > limit) {
      gamma[c * k + 3] *= limit / rolling;
      gamma[c * k + 4] *= limit / rolling;
    }
    gamma[c * k + 5] = std::clamp(gamma[c * k + 5], -limit, limit);
  });
}

void SphereContacts::diagonal(const CcpBodies& bodies, std::span<Real> out) const {
  const std::size_t k = rows_per_contact();
  exec::Default::for_each_light(contacts_.size(), [&](std::size_t c) {
    const Contact& contact = contacts_[c];
    const Real d =
        (contact.a != kWorld ? bodies.inverse_mass[contact.a] : 0) + bodies.inverse_mass[contact.b];
    for (std::size_t r = 0; r < std::min<std::size_t>(k, 3); ++r) out[c * k + r] = d;
    // The torques' rows turn the spheres only.
    const Real turn = (contact.a != kWorld ? bodies.inverse_inertia_scalar[contact.a] : 0) +
                      bodies.inverse_inertia_scalar[contact.b];
    for (std::size_t r = 3; r < k; ++r) out[c * k + r] = turn;
  });
}

void SphereContacts::warm_start(std::span<Real> gamma) const {
  std::copy(impulse_.begin(), impulse_.end(), gamma.begin());
}

void SphereContacts::store(std::span<const Real> gamma) {
  impulse_.assign(gamma.begin(), gamma.end());
}

}  // namespace sluice
