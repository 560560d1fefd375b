// Boundary treatments found by name: how a particle model makes its walls and bodies felt
// (Adami's extrapolated wall particles for wcsph today; penalty forces and MPS dummy layers
// next). A treatment is a plug-in behind a small interface that the model defines (the model
// hands it what it reads, its Context); a model reads `model.boundary` and makes the treatment
// of that name, and the "available: ..." list of an unknown name is the registry's.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace sluice {

// Sets the boundary particles' state from the fluid around them, before the model's forces.
template <class Context>
class BoundaryTreatment {
 public:
  virtual ~BoundaryTreatment() = default;
  virtual void update(Context& context) = 0;
};

template <class Context>
class BoundaryRegistry {
 public:
  using Factory = std::function<std::unique_ptr<BoundaryTreatment<Context>>()>;
  void add(const std::string& name, Factory factory) { factories_[name] = std::move(factory); }
  // The registered names, in alphabetical order.
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& entry : factories_) out.push_back(entry.first);
    return out;
  }
  // The treatment of that name; null when none is registered (the model's reader checks the
  // name against names() first, naming the file, line and key).
  std::unique_ptr<BoundaryTreatment<Context>> make(const std::string& name) const {
    const auto found = factories_.find(name);
    return found == factories_.end() ? nullptr : found->second();
  }

 private:
  std::map<std::string, Factory> factories_;
};

}  // namespace sluice
