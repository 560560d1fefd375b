// The contacts of a granular fluid's spheres with each other and with the walls (seed 001's
// fourth method: water as many frictionless spheres): millions of them, each stored compactly
// (its two bodies, the normal, the two radii along it, the least normal velocity), with one
// unknown (frictionless), a cone of three (friction, cohesion), or six with rolling resistance
// (a torque of at most mu_r r n about the tangents and the normal, r the pair's reduced
// radius, n the normal impulse; the sliding cone is projected first, then the torques are
// clamped to the new normal impulse, as in Tasora & Anitescu, Meccanica 48, 2013). A sphere's
// impulses reach it
// through a list of its own contacts, so that each sphere's velocity change is summed by one
// thread in a fixed order; the rest runs contact by contact. Impulses carry over to the next
// step by the spheres' identities: a contact is kept under the smaller identity of its two
// spheres (a wall's contact under its sphere's) with the other's identity (or the wall's code).
#pragma once

#include <cstdint>
#include <vector>

#include "sluice/ccp/constraint_group.hpp"
#include "sluice/ccp/sphere_contact_rows.hpp"
#include "sluice/core/state_archive.hpp"

namespace sluice {

inline void archive_state(StateArchive& a, SphereContact& c) {
  a(c.a, c.b, c.owner, c.partner, c.normal, c.radius_a, c.radius_b, c.target);
}

class SphereContacts final : public ConstraintGroup {
 public:
  static constexpr std::uint32_t kWorld = kSphereWorld;
  // The partner code of a contact with wall w.
  static constexpr std::uint32_t wall_code(std::uint32_t w) { return 0xFFFF0000u + w; }

  using Contact = SphereContact;
  // Starts a step: the spheres are bodies [first, first + count) of the problem, each known by
  // an identity below `identities`; friction mu, cohesion c [N s] and rolling friction mu_r
  // (needs mu > 0) for every contact.
  void begin(std::size_t first, std::size_t count, std::size_t identities, Real friction,
             Real cohesion, Real rolling_friction = 0);
  // The step's contacts, to fill (in any order that does not depend on the thread count).
  std::vector<Contact>& contacts() { return contacts_; }
  const std::vector<Contact>& contacts() const { return contacts_; }
  // After filling: each sphere's list of contacts, and the last step's impulses where the same
  // contact lasts.
  void finish();

  std::size_t rows_per_contact() const {
    return friction_ > 0 ? (rolling_friction_ > 0 ? 6 : 3) : 1;
  }
  // The normal impulse of contact c [N s].
  Real normal_impulse(std::size_t c) const { return impulse_[c * rows_per_contact()]; }

  std::size_t size() const override { return contacts_.size() * rows_per_contact(); }
  void row_velocities(const BodyVelocities& u, std::span<Real> out) const override;
  void apply_impulses(const CcpBodies& bodies, std::span<const Real> gamma,
                      BodyVelocities& u) const override;
  void project(std::span<Real> gamma) const override;
  void diagonal(const CcpBodies& bodies, std::span<Real> out) const override;
  void warm_start(std::span<Real> gamma) const override;
  void store(std::span<const Real> gamma) override;

  // The contacts as plain arrays (sphere_contact_rows.hpp), for a device's copy: the rows, each
  // sphere's list of its contacts, and the settings of every contact.
  SphereRows rows() const { return {contacts_.data(), tangents_.data(), rows_per_contact()}; }
  std::size_t tangent_count() const { return tangents_.size(); }
  const std::vector<std::uint32_t>& list_offsets() const { return list_offsets_; }
  const std::vector<SphereContactEntry>& list() const { return list_; }
  std::size_t first() const { return first_; }
  std::size_t count() const { return count_; }
  Real friction() const { return friction_; }
  Real cohesion() const { return cohesion_; }
  Real rolling_friction() const { return rolling_friction_; }

  // Checkpoints: the last step's contacts and impulses, which the next step's warm start
  // reads, with the settings that shape them.
  void archive_state(StateArchive& a) {
    a(first_, count_, identities_, friction_, cohesion_, rolling_friction_, contacts_, impulse_);
  }

 private:
  // The last step's impulses, listed by owner identity: [offsets[id], offsets[id + 1]).
  struct Memory {
    std::vector<std::uint32_t> offsets, partner;
    std::vector<Real> impulse;
  };
  void remember();

  std::size_t first_ = 0, count_ = 0, identities_ = 0;
  Real friction_ = 0, cohesion_ = 0, rolling_friction_ = 0;
  std::vector<Contact> contacts_;
  std::vector<Real> impulse_;
  // Each sphere's contacts (SphereContactEntry), from list_offsets_[s].
  using Entry = SphereContactEntry;
  std::vector<std::uint32_t> list_offsets_;
  std::vector<Entry> list_;
  std::vector<Vec3> tangents_;  // with friction: contact c's two, at 2 c and 2 c + 1
  Memory memory_;
};

}  // namespace sluice
