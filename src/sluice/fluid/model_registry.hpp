// Fluid models found by name: each model registers a factory under the name a case gives in
// `model.name`; an unknown name is an input error that lists what is registered.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sluice/coupling/body_geometry.hpp"
#include "sluice/fluid/fluid_system.hpp"
#include "sluice/io/case_config.hpp"

namespace sluice {

// Reads the model's parameters from the case (throws InputError) and builds it, ready to step.
using FluidFactory =
    std::function<std::unique_ptr<FluidSystem>(const io::CaseConfig&, const BodyGeometry&)>;

// What a model changes in the case before anything is built: bodies it adds to the case's own
// (penalty-sph: the grains of its free solid layers), the contact method it needs (granular).
// Throws InputError.
using CasePreparation = std::function<void(io::CaseConfig&)>;

class ModelRegistry {
 public:
  void add(const std::string& name, FluidFactory factory, CasePreparation prepare = {}) {
    factories_[name] = {std::move(factory), std::move(prepare)};
  }
  // The registered names, in alphabetical order.
  std::vector<std::string> names() const;
  // The model the case names (throws InputError naming model.name when none is registered).
  std::unique_ptr<FluidSystem> make(const io::CaseConfig& config, const BodyGeometry& bodies) const;
  // The case as its model prepares it (throws InputError).
  io::CaseConfig prepared(io::CaseConfig config) const;

 private:
  struct Entry {
    FluidFactory make;
    CasePreparation prepare;
  };
  std::map<std::string, Entry> factories_;
};

// Every model sluice ships, for a case of dimension D.
template <int D>
ModelRegistry shipped_models();

// The fluid of a case: the model it names among `models`, or, for a case of bodies alone,
// the bodies' surface particles.
template <int D>
std::unique_ptr<FluidSystem> make_fluid_system(const io::CaseConfig& config,
                                               const BodyGeometry& bodies,
                                               const ModelRegistry& models);

}  // namespace sluice
