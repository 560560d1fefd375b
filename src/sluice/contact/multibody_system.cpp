#include "sluice/contact/multibody_system.hpp"

namespace sluice {

namespace {
std::unique_ptr<PenaltyContactSolver> penalty_solver(Vec3 gravity, double substep_fraction) {
  return std::make_unique<PenaltyContactSolver>(gravity, substep_fraction);
}
}  // namespace

MultibodySystem::MultibodySystem(double contact_distance, Vec3 gravity, double substep_fraction)
    : rigid_(gravity) {
  auto solver = penalty_solver(gravity, substep_fraction);
  penalty_ = solver.get();
  contact_ = std::make_unique<ContactPipeline>(contact_distance, std::move(solver));
  rigid_.set_interaction(contact_.get());
}

std::size_t MultibodySystem::add(ContactBody body) {
  contact_->add(static_cast<ContactShape&&>(body));
  return rigid_.add(static_cast<SystemBody&&>(body));
}

}  // namespace sluice
