#include "sluice/fluid/model_registry.hpp"

#include <fmt/format.h>

#include "sluice/fluid/body_particles.hpp"
#include "sluice/fluid/constraint/constraint_factory.hpp"
#include "sluice/fluid/constraint/constraint_parameters.hpp"
#include "sluice/fluid/granular/granular_factory.hpp"
#include "sluice/fluid/granular/granular_parameters.hpp"
#include "sluice/fluid/mac/mac_factory.hpp"
#include "sluice/fluid/mps/mps_factory.hpp"
#include "sluice/fluid/penalty_sph/penalty_sph_factory.hpp"
#include "sluice/fluid/penalty_sph/penalty_sph_parameters.hpp"
#include "sluice/fluid/wcsph/wcsph_factory.hpp"

namespace sluice {

std::vector<std::string> ModelRegistry::names() const {
  std::vector<std::string> out;
  for (const auto& entry : factories_) out.push_back(entry.first);
  return out;
}

std::unique_ptr<FluidSystem> ModelRegistry::make(const io::CaseConfig& config,
                                                 const BodyGeometry& bodies) const {
  if (const auto found = factories_.find(config.model_name); found != factories_.end())
    return found->second.make(config, bodies);
  io::MapReader model(config.source, config.model, "model", config.model_line);
  model.fail_choice("name", "model", config.model_name, names());
}

io::CaseConfig ModelRegistry::prepared(io::CaseConfig config) const {
  if (!config.has_fluid()) return config;
  const auto found = factories_.find(config.model_name);
  if (found != factories_.end() && found->second.prepare) found->second.prepare(config);
  return config;
}

template <int D>
ModelRegistry shipped_models() {
  ModelRegistry registry;
  registry.add("wcsph", make_wcsph<D>);
  registry.add("mps", make_mps<D>);
  registry.add("penalty-sph", make_penalty_sph<D>, [](io::CaseConfig& config) {
    for (io::BodyConfig& b : free_solid_grains(config)) config.bodies.push_back(std::move(b));
  });
  registry.add("granular", make_granular<D>, prepare_granular_case);
  registry.add("constraint", make_constraint<D>, prepare_constraint_case);
  registry.add("mac", make_mac<D>);
  return registry;
}

template <int D>
std::unique_ptr<FluidSystem> make_fluid_system(const io::CaseConfig& config,
                                               const BodyGeometry& bodies,
                                               const ModelRegistry& models) {
  if (!config.has_fluid()) return std::make_unique<BodyParticles<D>>(config, bodies);
  return models.make(config, bodies);
}

template ModelRegistry shipped_models<2>();
template ModelRegistry shipped_models<3>();
template std::unique_ptr<FluidSystem> make_fluid_system<2>(const io::CaseConfig&,
                                                           const BodyGeometry&,
                                                           const ModelRegistry&);
template std::unique_ptr<FluidSystem> make_fluid_system<3>(const io::CaseConfig&,
                                                           const BodyGeometry&,
                                                           const ModelRegistry&);

}  // namespace sluice
