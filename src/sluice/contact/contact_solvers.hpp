// Contact solvers found by name (a case's `contact.method`): each registers a factory; the
// case reader's "expected one of" list is the registry's. `penalty` (forces, sub-cycled) and
// `complementarity` (cones of the velocity step) ship.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sluice/contact/contact_solver.hpp"

namespace sluice {

struct ContactSolverSettings {
  Vec3 gravity = Vec3::Zero();
  double substep_fraction = 1.0 / 30;  // penalty: solid step / shortest contact period
};

using ContactSolverFactory =
    std::function<std::unique_ptr<ContactSolver>(const ContactSolverSettings&)>;

class ContactSolverRegistry {
 public:
  void add(const std::string& name, ContactSolverFactory factory) {
    factories_[name] = std::move(factory);
  }
  // The registered names, in alphabetical order.
  std::vector<std::string> names() const;
  // The solver of that name; std::invalid_argument (listing the names) when none is.
  std::unique_ptr<ContactSolver> make(const std::string& name,
                                      const ContactSolverSettings& settings) const;

 private:
  std::map<std::string, ContactSolverFactory> factories_;
};

// Every contact solver sluice ships.
ContactSolverRegistry shipped_contact_solvers();

}  // namespace sluice
