// The rigid bodies of a run, advanced together by one of two methods, as their interaction
// asks (BodyInteraction::in_velocity_step).
// Penalty (seed 000's solid sub-cycling): a step of the caller (the fluid's) is split into as
// many solid sub-steps as the stiffest interaction between bodies needs; forces from outside
// (the fluid's) are held over the sub-steps, the interaction (contact springs) is evaluated
// at each, and joints and a participant's rows are met at each, velocity-level.
// Complementarity (seed 001's non-smooth dynamics; Anitescu & Tasora 2010): one step of the
// caller's length, semi-implicit: the bodies' velocities are predicted with the outside forces
// and gravity, the contacts (friction cones), joints and a participant's bodies and rows form
// one cone complementarity problem (ccp/), and its impulses give the new velocities, with
// which the bodies move.
#pragma once

#include <functional>
#include <vector>

#include "sluice/ccp/ccp_solver.hpp"
#include "sluice/ccp/row_group.hpp"
#include "sluice/rigid/body_interaction.hpp"
#include "sluice/rigid/body_sharing.hpp"
#include "sluice/rigid/ccp_participant.hpp"
#include "sluice/rigid/joint.hpp"
#include "sluice/rigid/rigid_body.hpp"

namespace sluice {

struct RigidSystemEnergy {
  double kinetic = 0;
  double potential = 0;  // in the gravity field, relative to z = 0 along -g
  double elastic = 0;    // stored in the interaction (contact springs)
  double total() const { return kinetic + potential + elastic; }
};

// The velocity-level step's settings: the solver, how contacts recover from a penetration and
// how joints take back their drift.
struct VelocityStepSettings {
  CcpSettings solver;
  double recovery_speed = 0.1;  // the fastest a penetrating contact is pushed apart [m/s]
  double stabilisation = 0.2;   // of a joint's error taken back in a step (Baumgarte)
  // Solves again with each contact's normal target raised by mu |slip| of the last solve, up
  // to this many times: the cone complementarity's lift-off of a slipping contact cancelled
  // (RowGroup::correct_slip). 0: the relaxed law alone.
  int slip_iterations = 0;
};

// What the velocity-level solves of a run took.
struct VelocityStepTotals {
  long solves = 0;
  long iterations = 0;
  int most_iterations = 0;
  double residual_sum = 0, largest_residual = 0;  // [m/s]
};

class RigidSystem {
 public:
  explicit RigidSystem(Vec3 gravity) : gravity_(gravity) {}

  std::size_t add(SystemBody body);
  // The forces between bodies; not owned, must outlive the system (nullptr: none).
  void set_interaction(BodyInteraction* interaction) { interaction_ = interaction; }
  void set_velocity_step(const VelocityStepSettings& settings) { velocity_step_ = settings; }
  // Whether the bodies advance by the complementarity method (the interaction's contacts as
  // cones of one velocity-level step), not by the penalty method's sub-steps.
  bool complementarity() const { return interaction_ && interaction_->in_velocity_step(); }
  void add_joint(const Joint& joint) { joints_.push_back(joint); }
  // A split run's division of the bodies between its processes (not owned; nullptr: this
  // process advances every body). The penalty method only.
  void set_sharing(BodySharing* sharing) { sharing_ = sharing; }
  const std::vector<Joint>& joints() const { return joints_; }

  // Advances by dt. `force` and `torque` (one per body, may be empty) are held over the step.
  // `participant` (may be null) adds its bodies and rows to every velocity-level solve.
  // Returns the number of sub-steps taken (complementarity: 1).
  int advance(double dt, const std::vector<Vec3>& force = {}, const std::vector<Vec3>& torque = {},
              CcpParticipant* participant = nullptr);
  // The sub-step the interaction needs over a coming step of dt (dt when it needs none
  // shorter; complementarity: dt).
  double solid_step(double dt);

  const std::vector<SystemBody>& bodies() const { return bodies_; }
  std::vector<SystemBody>& bodies() { return bodies_; }
  RigidSystemEnergy energy() const;
  // The interaction's force and torque (about the centre of mass) on each body at the last
  // sub-step (complementarity: the contacts' impulses over the step).
  const std::vector<Vec3>& interaction_force() const { return interaction_force_; }
  const std::vector<Vec3>& interaction_torque() const { return interaction_torque_; }
  long substeps_taken() const { return substeps_; }
  const VelocityStepTotals& velocity_steps() const { return totals_; }
  // The rows of the last velocity-level solve: contacts and joints, with their impulses.
  const RowGroup& contact_rows() const { return contact_rows_; }
  const RowGroup& joint_rows() const { return joint_rows_; }

  // Checkpoints: the bodies' motion, the clock of prescribed motion, the interaction's last
  // force (the next step's first half-kick), the joints' impulses (their warm start), totals.
  void archive_state(StateArchive& a);

 private:
  void evaluate_interaction(double dt);
  void advance_complementarity(double dt, const std::vector<Vec3>& force,
                               const std::vector<Vec3>& torque, CcpParticipant* participant);
  // Meets the joints' and the participant's rows (and, with `contacts`, the contacts) for a
  // step of h at the bodies' present velocities, which it replaces. The joints take back
  // `stabilisation` of their drift in the step (Baumgarte); 0 only projects the velocities.
  void solve_velocities(double h, bool contacts, CcpParticipant* participant, double stabilisation);
  bool has_velocity_rows(const CcpParticipant* participant) const {
    return !joints_.empty() || participant != nullptr;
  }
  // Whether this process advances body b (a joint's end may be the world: never here).
  bool here(std::size_t b) const { return b < bodies_.size() && (here_.empty() || here_[b]); }
  bool moves(std::size_t b) const { return !bodies_[b].fixed && here(b); }

  Vec3 gravity_;
  std::vector<SystemBody> bodies_;
  BodyInteraction* interaction_ = nullptr;
  VelocityStepSettings velocity_step_;
  std::vector<Joint> joints_;
  std::vector<Vec3> interaction_force_, interaction_torque_;
  long substeps_ = 0;
  double time_ = 0;
  CcpProblem problem_;
  RowGroup contact_rows_, joint_rows_;
  BodyVelocities velocities_;
  VelocityStepTotals totals_;
  BodySharing* sharing_ = nullptr;
  std::vector<bool> here_;  // the bodies this process advances in the present step (empty: all)
};

}  // namespace sluice
