#include "sluice/contact/contact_solvers.hpp"

#include <stdexcept>

#include "sluice/contact/complementarity_contact_solver.hpp"
#include "sluice/contact/penalty_contact_solver.hpp"

namespace sluice {

std::vector<std::string> ContactSolverRegistry::names() const {
  std::vector<std::string> out;
  for (const auto& entry : factories_) out.push_back(entry.first);
  return out;
}

std::unique_ptr<ContactSolver> ContactSolverRegistry::make(
    const std::string& name, const ContactSolverSettings& settings) const {
  const auto found = factories_.find(name);
  if (found == factories_.end()) {
    std::string available;
    for (const std::string& n : names()) available += (available.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown contact solver '" + name + "'; available: " + available);
  }
  return found->second(settings);
}

ContactSolverRegistry shipped_contact_solvers() {
  ContactSolverRegistry registry;
  registry.add("penalty", [](const ContactSolverSettings& s) {
    return std::make_unique<PenaltyContactSolver>(s.gravity, s.substep_fraction);
  });
  registry.add("complementarity", [](const ContactSolverSettings&) {
    return std::make_unique<ComplementarityContactSolver>();
  });
  return registry;
}

}  // namespace sluice
