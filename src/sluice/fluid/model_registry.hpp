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

class ModelRegistry {
 public:
  void add(const std::string& name, FluidFactory factory) { factories_[name] = std::move(factory); }
  // The registered names, in alphabetical order.
  std::vector<std::string> names() const;
  // The model the case names (throws InputError naming model.name when none is registered).
  std::unique_ptr<FluidSystem> make(const io::CaseConfig& config, const BodyGeometry& bodies) const;

 private:
  std::map<std::string, FluidFactory> factories_;
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
