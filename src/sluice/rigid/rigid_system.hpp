// The rigid bodies of a run, advanced together (seed 000's solid sub-cycling): a step of the
// caller (the fluid's) is split into as many solid sub-steps as the stiffest interaction
// between bodies needs; with none it is one step. Forces from outside (the fluid's) are held
// over the sub-steps; the interaction between the bodies (contact) is evaluated at each, and
// velocity constraints (a monolithic coupling's) are solved in each.
#pragma once

#include <functional>
#include <vector>

#include "sluice/rigid/body_interaction.hpp"
#include "sluice/ccp/constraint_row.hpp"
#include "sluice/rigid/rigid_body.hpp"

namespace sluice {

struct RigidSystemEnergy {
  double kinetic = 0;
  double potential = 0;  // in the gravity field, relative to z = 0 along -g
  double elastic = 0;    // stored in the interaction (contact springs)
  double total() const { return kinetic + potential + elastic; }
};

class RigidSystem {
 public:
  explicit RigidSystem(Vec3 gravity) : gravity_(gravity) {}

  std::size_t add(SystemBody body);
  // The forces between bodies; not owned, must outlive the system (nullptr: none).
  void set_interaction(BodyInteraction* interaction) { interaction_ = interaction; }

  // Advances by dt. `force` and `torque` (one per body, may be empty) are held over the
  // sub-steps. `rows` (may be null) are velocity constraints solved together in every
  // sub-step, on the velocity the bodies drift with (after the first half kick), warm-started
  // from the last sub-step's impulses. Returns the number of sub-steps taken.
  int advance(double dt, const std::vector<Vec3>& force = {}, const std::vector<Vec3>& torque = {},
              std::vector<ConstraintRow>* rows = nullptr);
  // The sub-step the interaction needs over a coming step of dt (dt when it needs none shorter).
  double solid_step(double dt);

  const std::vector<SystemBody>& bodies() const { return bodies_; }
  std::vector<SystemBody>& bodies() { return bodies_; }
  RigidSystemEnergy energy() const;
  // The interaction's force and torque (about the centre of mass) on each body at the last
  // sub-step.
  const std::vector<Vec3>& interaction_force() const { return interaction_force_; }
  const std::vector<Vec3>& interaction_torque() const { return interaction_torque_; }
  long substeps_taken() const { return substeps_; }

 private:
  void evaluate_interaction(double dt);

  Vec3 gravity_;
  std::vector<SystemBody> bodies_;
  BodyInteraction* interaction_ = nullptr;
  std::vector<Vec3> interaction_force_, interaction_torque_;
  long substeps_ = 0;
  double time_ = 0;
};

}  // namespace sluice
