// Rigid bodies in contact (seed 000: Amaro Junior, Cheng & Osello 2019), assembled: the rigid
// system (integration, solid sub-cycling, energy; rigid/rigid_system.hpp) with the contact
// pipeline (contact_pipeline.hpp) and a contact solver by name (contact_solvers.hpp).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sluice/contact/contact_body.hpp"
#include "sluice/contact/contact_pipeline.hpp"
#include "sluice/rigid/rigid_system.hpp"

namespace sluice {

class MultibodySystem {
 public:
  // contact_distance: particle pairs closer than this are examined (about the spacing).
  // substep_fraction: solid step = this fraction of the shortest contact period (1/20-1/50).
  // solver: a name in shipped_contact_solvers().
  MultibodySystem(double contact_distance, Vec3 gravity, double substep_fraction = 1.0 / 30,
                  const std::string& solver = "penalty");

  std::size_t add(ContactBody body);

  // The velocity-level step's settings (joints; contacts too where the solver is of the
  // velocity step).
  void set_velocity_step(const VelocityStepSettings& settings) {
    rigid_.set_velocity_step(settings);
  }
  void add_joint(const Joint& joint) { rigid_.add_joint(joint); }
  // A split run's division of the bodies between its ranks (RigidSystem::set_sharing).
  void set_sharing(BodySharing* sharing) { rigid_.set_sharing(sharing); }

  // Advances by dt. `force` and `torque` (one per body, may be empty) are held over the
  // sub-steps, as the fluid's force is; `participant` (may be null) joins every velocity-level
  // solve (RigidSystem::advance). Returns the number of sub-steps taken.
  int advance(double dt, const std::vector<Vec3>& force = {}, const std::vector<Vec3>& torque = {},
              CcpParticipant* participant = nullptr) {
    return rigid_.advance(dt, force, torque, participant);
  }
  // The solid step that the contacts in reach during a coming step of dt need: a
  // `substep_fraction` of the shortest contact period among them; dt when none is in reach.
  double solid_step(double dt) { return rigid_.solid_step(dt); }

  const std::vector<SystemBody>& bodies() const { return rigid_.bodies(); }
  std::vector<SystemBody>& bodies() { return rigid_.bodies(); }
  const ContactShape& shape(std::size_t b) const { return contact_->shapes()[b]; }
  const ContactPipeline& contact() const { return *contact_; }
  RigidSystemEnergy energy() const { return rigid_.energy(); }
  // Contact force and torque (about the centre of mass) on each body from the last sub-step.
  const std::vector<Vec3>& contact_force() const { return rigid_.interaction_force(); }
  const std::vector<Vec3>& contact_torque() const { return rigid_.interaction_torque(); }
  // The deepest overlap at any sub-step so far (penalty solver; 0 for another).
  double deepest_overlap_ever() const { return contact_->solver().deepest_overlap_ever(); }
  long substeps_taken() const { return rigid_.substeps_taken(); }
  const RigidSystem& rigid() const { return rigid_; }

  // Checkpoints: the bodies and their contacts.
  void archive_state(StateArchive& a) {
    rigid_.archive_state(a);
    contact_->archive_state(a);
  }

 private:
  // On the heap, so that the rigid system's pointer to it survives moving the system.
  std::unique_ptr<ContactPipeline> contact_;
  RigidSystem rigid_;
};

}  // namespace sluice
