#include "sluice/contact/multibody_system.hpp"

#include "sluice/contact/contact_solvers.hpp"

namespace sluice {

MultibodySystem::MultibodySystem(double contact_distance, Vec3 gravity, double substep_fraction,
                                 const std::string& solver_name)
    : rigid_(gravity) {
  contact_ = std::make_unique<ContactPipeline>(
      contact_distance, shipped_contact_solvers().make(solver_name, {gravity, substep_fraction}));
  rigid_.set_interaction(contact_.get());
}

std::size_t MultibodySystem::add(ContactBody body) {
  contact_->add(static_cast<ContactShape&&>(body));
  return rigid_.add(static_cast<SystemBody&&>(body));
}

}  // namespace sluice
