// Fluid models found by name: each model registers a factory under the name a case gives in
// `model.name`; an unknown name is an input error that lists what is registered.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sluice/fluid/model_entry.hpp"

namespace sluice {

class ModelRegistry {
 public:
  void add(const std::string& name, ModelEntry entry) { entries_[name] = std::move(entry); }
  // A model known by its factory alone: the case as it is, the largest size, the CPU only.
  void add(const std::string& name, FluidFactory make) {
    ModelEntry entry;
    entry.make = std::move(make);
    add(name, std::move(entry));
  }
  // The registered names, in alphabetical order.
  std::vector<std::string> names() const;
  // The names of the models that run on `device`, in alphabetical order.
  std::vector<std::string> names_on(const std::string& device) const;
  // The entry of the model named `name`, or null.
  const ModelEntry* find(const std::string& name) const;
  // The model the case names (throws InputError naming model.name when none is registered).
  std::unique_ptr<FluidSystem> make(const io::CaseConfig& config, const BodyGeometry& bodies,
                                    const ModelServices& services) const;
  // The case as its model prepares it (throws InputError).
  io::CaseConfig prepared(io::CaseConfig config) const;
  // The coupling scheme of the case: its `coupling.scheme`, which its model must support, or
  // the model's own (held-loads for a case of bodies alone). Throws InputError naming
  // coupling.scheme and the schemes the model supports.
  std::string coupling_scheme(const io::CaseConfig& config) const;

 private:
  // The names of the models that have `feature` (ModelEntry::open_boundaries ...), in
  // alphabetical order as a phrase: "mac, mps and wcsph".
  std::string names_with(bool ModelEntry::*feature) const;

  std::map<std::string, ModelEntry> entries_;
};

// The fluid of a case: the model it names among `models`, or, for a case of bodies alone,
// the bodies' surface particles.
template <int D>
std::unique_ptr<FluidSystem> make_fluid_system(const io::CaseConfig& config,
                                               const BodyGeometry& bodies,
                                               const ModelRegistry& models,
                                               const ModelServices& services);

}  // namespace sluice
