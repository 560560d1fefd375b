// A body of the rigid system, and the interface through which bodies push on each other.
// The rigid system integrates; what the forces are (a penalty contact law today) lives behind
// this interface, in contact/.
#pragma once

#include <functional>
#include <vector>

#include "sluice/ccp/row_group.hpp"
#include "sluice/core/state_archive.hpp"
#include "sluice/rigid/body_islands.hpp"
#include "sluice/rigid/rigid_body.hpp"

namespace sluice {

struct SystemBody {
  RigidBody state;
  bool fixed = false;  // walls, fixed and prescribed bodies: infinite mass, not moved by forces
  // A prescribed body: sets its state (pose and velocities) at a time; called every sub-step.
  std::function<void(double time, RigidBody& state)> prescribed;
};

// Forces between bodies that depend on their states, evaluated at every solid sub-step; or
// the contacts as rows of the velocity-level step (complementarity).
class BodyInteraction {
 public:
  virtual ~BodyInteraction() = default;
  // Whether the bodies meet as rows of the velocity-level step (contact_constraints) rather
  // than by forces over sub-steps (evaluate, stable_step).
  virtual bool in_velocity_step() const { return false; }
  // Force and torque (about each centre of mass) on every body for the bodies' present states;
  // `dt` is the sub-step the forces act over (0: evaluate only), for laws with a history.
  // `force` and `torque` come sized to the bodies and zeroed.
  virtual void evaluate(const std::vector<SystemBody>& bodies, double dt, std::vector<Vec3>& force,
                        std::vector<Vec3>& torque) = 0;
  // The sub-step the interaction needs over a coming step of dt (dt when none shorter).
  virtual double stable_step(const std::vector<SystemBody>& bodies, double dt) = 0;
  // The energy stored in it at the last evaluation (contact springs).
  virtual double stored_energy() const = 0;
  // The contacts within reach as friction cones for a step of h: each asks its normal
  // velocity to be at least minus its gap over h (a penetration: to separate at up to
  // `recovery_speed`). Warm-started from the last call's impulses where a contact lasts.
  virtual void contact_constraints(const std::vector<SystemBody>& /*bodies*/, double /*h*/,
                                   double /*recovery_speed*/, RowGroup& /*rows*/) {}
  // The rows of contact_constraints after the solve, with their impulses.
  virtual void remember_contact_impulses(const RowGroup& /*rows*/) {}

  // A split run (rigid/body_sharing.hpp). Each process evaluates only the pairs with a body
  // marked in `here` (empty: every pair); no pair joins bodies of two processes.
  virtual void evaluate_only(const std::vector<bool>& /*here*/) {}
  // The pairs of bodies that could come within reach of each other over a coming step of dt,
  // with a margin: what ties bodies into islands.
  virtual std::vector<IslandPair> pairs_in_reach(const std::vector<SystemBody>& /*bodies*/,
                                                 double /*dt*/) {
    return {};
  }
  // This process's part of the interaction's state (its pairs' contacts and figures), and
  // back from every process's part (in rank order) the whole state as one process holds it.
  virtual void write_share(StateArchive& /*a*/) {}
  virtual void read_shares(std::vector<StateArchive>& /*parts*/) {}
};

}  // namespace sluice
