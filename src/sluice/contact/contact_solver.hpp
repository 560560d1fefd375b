// The last stage of contact: what the contact set does to the bodies. A solver works in one of
// two ways, and the rigid system steps the bodies as it asks (rigid/rigid_system.hpp):
//   forces        each contact a force over solid sub-steps short enough for its stiffness
//                 (the penalty law, penalty_contact_solver.hpp; seed 000);
//   velocity step each contact a friction cone of the bodies' velocity-level step, solved with
//                 the joints as one complementarity problem (complementarity_contact_solver.hpp;
//                 seed 001).
#pragma once

#include <limits>
#include <vector>

#include "sluice/ccp/row_group.hpp"
#include "sluice/contact/contact_body.hpp"
#include "sluice/contact/contact_set.hpp"

namespace sluice {

class ContactSolver {
 public:
  virtual ~ContactSolver() = default;
  // True for a solver of the velocity step (cones), false for one of forces.
  virtual bool in_velocity_step() const = 0;

  // Forces: adds the contacts' force and torque (about each centre of mass) on every body;
  // `dt` is the sub-step they act over (0: evaluate only). May update each contact's history.
  virtual void solve(ContactSet& /*contacts*/, const std::vector<SystemBody>& /*bodies*/,
                     const std::vector<ContactShape>& /*shapes*/, double /*dt*/,
                     std::vector<Vec3>& /*force*/, std::vector<Vec3>& /*torque*/) {}
  // Forces: the sub-step that bodies a and b, approaching at up to `approach` m/s, need
  // (infinite for a solver of the velocity step).
  virtual double pair_step(std::size_t /*a*/, std::size_t /*b*/, double /*approach*/,
                           const std::vector<SystemBody>& /*bodies*/,
                           const std::vector<ContactShape>& /*shapes*/) {
    return std::numeric_limits<double>::infinity();
  }

  // Velocity step: the contacts as friction cones for a step of h: each asks its normal
  // velocity to be at least minus its gap over h (a penetration: to separate at up to
  // `recovery_speed`).
  virtual void add_cones(const ContactSet& /*contacts*/, const std::vector<SystemBody>& /*bodies*/,
                         const std::vector<ContactShape>& /*shapes*/, double /*h*/,
                         double /*recovery_speed*/, RowGroup& /*rows*/) {}
  // Velocity step: the cones of add_cones after the solve, with their impulses.
  virtual void remember_impulses(const RowGroup& /*rows*/) {}

  // The energy stored in the contacts at the last solve (springs; 0 for cones).
  virtual double stored_energy() const { return 0; }
  // The deepest overlap at any solve so far (forces; 0 where the solver does not track it).
  virtual double deepest_overlap_ever() const { return 0; }
  // Checkpoints: what the solver carries from one solve to the next.
  virtual void archive_state(StateArchive& a) = 0;

  // A split run, where each process solves the contacts of its own bodies: the figures of the
  // last solve here, and then those of every process's made one (energy summed, overlaps the
  // deepest), so that each sizes the next sub-step alike.
  struct Figures {
    double stored_energy = 0, deepest_overlap = 0, deepest_overlap_ever = 0;
  };
  virtual Figures figures() const { return {}; }
  virtual void set_figures(const Figures& /*figures*/) {}
};

}  // namespace sluice
