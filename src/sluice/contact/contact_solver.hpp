// The last stage of contact: forces (or, for a complementarity solver, impulses) on the bodies
// from the contact set. The penalty law is the first solver (penalty_contact_solver.hpp).
#pragma once

#include <vector>

#include "sluice/contact/contact_body.hpp"
#include "sluice/contact/contact_set.hpp"

namespace sluice {

class ContactSolver {
 public:
  virtual ~ContactSolver() = default;
  // Adds the contacts' force and torque (about each centre of mass) on every body; `dt` is the
  // sub-step they act over (0: evaluate only). May update each contact's history.
  virtual void solve(ContactSet& contacts, const std::vector<SystemBody>& bodies,
                     const std::vector<ContactShape>& shapes, double dt, std::vector<Vec3>& force,
                     std::vector<Vec3>& torque) = 0;
  // The sub-step that bodies a and b, approaching at up to `approach` m/s, need.
  virtual double pair_step(std::size_t a, std::size_t b, double approach,
                           const std::vector<SystemBody>& bodies,
                           const std::vector<ContactShape>& shapes) = 0;
  // The energy stored in the contacts at the last solve.
  virtual double stored_energy() const = 0;
  // Checkpoints: what the solver carries from one solve to the next.
  virtual void archive_state(StateArchive& a) = 0;
};

}  // namespace sluice
