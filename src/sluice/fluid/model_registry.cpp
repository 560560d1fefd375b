#include "sluice/fluid/model_registry.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "sluice/core/errors.hpp"
#include "sluice/coupling/coupling_scheme.hpp"
#include "sluice/fluid/body_particles.hpp"
#include "sluice/io/yaml_reader.hpp"

namespace sluice {

std::vector<std::string> ModelRegistry::names() const {
  std::vector<std::string> out;
  for (const auto& entry : entries_) out.push_back(entry.first);
  return out;
}

std::vector<std::string> ModelRegistry::names_on(const std::string& device) const {
  std::vector<std::string> out;
  for (const auto& [name, entry] : entries_) {
    if (std::find(entry.devices.begin(), entry.devices.end(), device) != entry.devices.end())
      out.push_back(name);
  }
  return out;
}

std::string ModelRegistry::names_with(bool ModelEntry::*feature) const {
  std::vector<std::string> names;
  for (const auto& [name, entry] : entries_)
    if (entry.*feature) names.push_back(name);
  std::string out;  // "mac, mps and wcsph"
  for (std::size_t k = 0; k < names.size(); ++k)
    out += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + names[k];
  return out;
}

const ModelEntry* ModelRegistry::find(const std::string& name) const {
  const auto found = entries_.find(name);
  return found != entries_.end() ? &found->second : nullptr;
}

std::unique_ptr<FluidSystem> ModelRegistry::make(const io::CaseConfig& config,
                                                 const BodyGeometry& bodies,
                                                 const ModelServices& services) const {
  if (const ModelEntry* entry = find(config.model_name)) {
    if (services.split() && !entry->one_rank_only.empty()) {
      throw InputError(config.file(), config.model_line, "model.name",
                       fmt::format("the {} model runs on one rank only ({}); run it without "
                                   "mpirun, or with -np 1",
                                   config.model_name, entry->one_rank_only));
    }
    if (!config.boundaries.empty()) {
      const io::BoundaryConfig& b = config.boundaries.front();
      if (!entry->open_boundaries) {
        throw InputError(config.file(), b.line, b.key + ".type",
                         fmt::format("the {} model has no open boundaries yet; {} have inlets "
                                     "and outlets",
                                     config.model_name, names_with(&ModelEntry::open_boundaries)));
      }
    }
    if (config.periodic && !entry->periodic) {
      throw InputError(config.file(), config.periodic->line, config.periodic->key + ".type",
                       fmt::format("the {} model has no periodic boundaries yet; {} have them",
                                   config.model_name, names_with(&ModelEntry::periodic)));
    }
    if (!entry->damping_zones && !config.damping.empty()) {
      const io::DampingZone& z = config.damping.front();
      throw InputError(config.file(), z.line, z.key,
                       fmt::format("the {} model has no damping zones yet; {} have them",
                                   config.model_name, names_with(&ModelEntry::damping_zones)));
    }
    return entry->make(config, bodies, services);
  }
  io::MapReader model(config.source, config.model, "model", config.model_line);
  model.fail_choice("name", "model", config.model_name, names());
}

io::CaseConfig ModelRegistry::prepared(io::CaseConfig config) const {
  if (!config.has_fluid()) {
    coupling_scheme(config);
    return config;
  }
  const ModelEntry* entry = find(config.model_name);
  if (entry != nullptr && entry->prepare) entry->prepare(config);
  coupling_scheme(config);  // a scheme the model does not support: refused before building
  return config;
}

std::string ModelRegistry::coupling_scheme(const io::CaseConfig& config) const {
  const ModelEntry* entry = config.has_fluid() ? find(config.model_name) : nullptr;
  const std::vector<std::string> supported =
      entry != nullptr ? entry->schemes : std::vector<std::string>{"held-loads"};
  const std::string& chosen = config.coupling.scheme;
  if (chosen.empty()) return supported.front();
  if (std::find(supported.begin(), supported.end(), chosen) != supported.end()) return chosen;
  const auto& [file, line] = config.coupling.scheme_place;
  const std::string who =
      config.has_fluid() ? "the " + config.model_name + " model" : "a case of bodies alone";
  const std::vector<std::string> every = coupling_scheme_names();
  std::string problem = io::unknown_choice("coupling scheme", chosen, every);
  if (std::find(every.begin(), every.end(), chosen) != every.end()) {
    problem =
        fmt::format("{} is coupled by {}, not '{}'", who, fmt::join(supported, " or "), chosen);
  }
  throw InputError(file, line, "coupling.scheme", problem);
}

template <int D>
std::unique_ptr<FluidSystem> make_fluid_system(const io::CaseConfig& config,
                                               const BodyGeometry& bodies,
                                               const ModelRegistry& models,
                                               const ModelServices& services) {
  if (!config.has_fluid()) {
    if (services.split()) {
      throw InputError(config.file(), 0, "",
                       "a case of bodies alone (no fluid) runs on one rank: run it without "
                       "mpirun, or with -np 1");
    }
    return std::make_unique<BodyParticles<D>>(config, bodies);
  }
  return models.make(config, bodies, services);
}

template std::unique_ptr<FluidSystem> make_fluid_system<2>(const io::CaseConfig&,
                                                           const BodyGeometry&,
                                                           const ModelRegistry&,
                                                           const ModelServices&);
template std::unique_ptr<FluidSystem> make_fluid_system<3>(const io::CaseConfig&,
                                                           const BodyGeometry&,
                                                           const ModelRegistry&,
                                                           const ModelServices&);

}  // namespace sluice
