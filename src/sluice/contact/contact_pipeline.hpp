// Contact between rigid bodies as one pipeline, run at every solid sub-step: place each body's
// surface particles, a broad phase on a grid (candidate body pairs), the narrow phase (particle
// pairs with face normals and gaps), a contact set with persistent identities, and a solver
// that turns the contacts into forces or into friction cones of the velocity step
// (contact_solver.hpp). The rigid system sees it as a BodyInteraction.
#pragma once

#include <memory>
#include <vector>

#include "sluice/contact/broad_phase.hpp"
#include "sluice/contact/contact_solver.hpp"
#include "sluice/contact/narrow_phase.hpp"
#include "sluice/contact/world_surface.hpp"
#include "sluice/rigid/body_interaction.hpp"

namespace sluice {

class ContactPipeline final : public BodyInteraction {
 public:
  // contact_distance: particle pairs closer than this are examined (about the spacing).
  ContactPipeline(double contact_distance, std::unique_ptr<ContactSolver> solver);

  // The shape of the next body of the rigid system (shapes and bodies share their indices).
  void add(ContactShape shape) { shapes_.push_back(std::move(shape)); }
  const std::vector<ContactShape>& shapes() const { return shapes_; }
  const ContactSet& contacts() const { return contacts_; }
  const ContactSolver& solver() const { return *solver_; }

  void evaluate(const std::vector<SystemBody>& bodies, double dt, std::vector<Vec3>& force,
                std::vector<Vec3>& torque) override;
  // The solver's step for every pair of bodies that can come within reach during dt.
  double stable_step(const std::vector<SystemBody>& bodies, double dt) override;
  double stored_energy() const override { return solver_->stored_energy(); }
  bool in_velocity_step() const override { return solver_->in_velocity_step(); }
  // The particle pairs that may close within the step (the contact distance apart) as the
  // solver's friction cones.
  void contact_constraints(const std::vector<SystemBody>& bodies, double h, double recovery_speed,
                           RowGroup& rows) override;
  void remember_contact_impulses(const RowGroup& rows) override {
    solver_->remember_impulses(rows);
  }
  void evaluate_only(const std::vector<bool>& here) override { here_ = here; }
  std::vector<IslandPair> pairs_in_reach(const std::vector<SystemBody>& bodies, double dt) override;
  void write_share(StateArchive& a) override;
  void read_shares(std::vector<StateArchive>& parts) override;

  // Checkpoints: the contacts with their histories and the solver's state (the bodies' places
  // and the candidate pairs are found anew each call).
  void archive_state(StateArchive& a) {
    a.section("contacts");
    a(contacts_);
    a.section(solver_->in_velocity_step() ? "contact_cones" : "contact_forces");
    solver_->archive_state(a);
  }

 private:
  // Each body's surface particles in the world; `here_only`: only the bodies this process
  // evaluates, and the fixed ones.
  void place(const std::vector<SystemBody>& bodies, bool here_only = false);
  // The broad phase's pairs, each body's box grown by `growth` (may be empty) and then by
  // `margin`; a plane wall's pairs also checked against its plane.
  void candidates(const std::vector<SystemBody>& bodies, const std::vector<double>& growth,
                  double margin);
  // Calls in_reach(a, b, approach) for each pair whose surfaces can come within `reach` times
  // their own travel over dt plus the contact distance (1: the step's reach), approach being
  // the fastest the two can close.
  template <class InReach>
  void each_pair_in_reach(const std::vector<SystemBody>& bodies, double dt, double reach,
                          InReach&& in_reach);

  double distance_;
  std::unique_ptr<ContactSolver> solver_;
  std::vector<ContactShape> shapes_;
  std::vector<WorldSurface> surfaces_;  // the shapes' particles in the world
  BroadPhase broad_phase_;
  NarrowPhase narrow_phase_;
  ContactSet contacts_;
  std::vector<AxisBox> boxes_;
  std::vector<bool> fixed_, large_;
  std::vector<BodyPair> pairs_;
  std::vector<bool> here_;  // the bodies this process evaluates (empty: all)
  // A split run's pairs in twice the step's reach, found by the last stable_step (over a step
  // of island_pairs_dt_; -1: none).
  std::vector<IslandPair> island_pairs_;
  double island_pairs_dt_ = -1;
};

}  // namespace sluice
