// Contact as friction cones of the bodies' velocity-level step (seed 001's non-smooth
// dynamics; Anitescu & Tasora 2010): each particle pair of a contact is one cone with the pair's
// smaller friction, warm-started from the impulses of the same contact's pair in the last
// solve. The rigid system solves the cones with the joints (rigid/rigid_system.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <unordered_map>

#include "sluice/contact/contact_solver.hpp"

namespace sluice {

class ComplementarityContactSolver final : public ContactSolver {
 public:
  bool in_velocity_step() const override { return true; }
  void add_cones(const ContactSet& contacts, const std::vector<SystemBody>& bodies,
                 const std::vector<ContactShape>& shapes, double h, double recovery_speed,
                 RowGroup& rows) override;
  void remember_impulses(const RowGroup& rows) override;
  // The last solve's impulses (the warm start).
  void archive_state(StateArchive& a) override { a(last_impulses_); }

 private:
  // The last solve's normal and tangential impulses by (contact id, pair index).
  std::unordered_map<std::uint64_t, std::array<Real, 3>> last_impulses_;
};

}  // namespace sluice
