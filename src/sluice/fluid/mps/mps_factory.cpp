#include "sluice/fluid/mps/mps_factory.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "sluice/core/errors.hpp"
#include "sluice/fluid/mps/mps_model.hpp"

namespace sluice {

namespace {

template <int D>
std::unique_ptr<FluidSystem> make_mps(const io::CaseConfig& config, const BodyGeometry& bodies,
                                      const ModelServices& services) {
  MpsParameters parameters = read_mps_parameters(config);
  parameters.solver_settings.hypre = services.hypre;
  const Communicator ranks = services.split() ? *services.ranks : Communicator::alone();
  if (ranks.split()) {
    if (parameters.emulated_device) {
      throw InputError(config.file(), config.model_line, "model.device",
                       "a run on several ranks runs on the CPU for now (device: cpu)");
    }
    const std::vector<std::string> split = split_solver_names();
    if (parameters.variant != MpsVariant::kExplicit &&
        std::find(split.begin(), split.end(), parameters.solver) == split.end()) {
      throw InputError(config.file(), config.model_line, "model.solver",
                       fmt::format("on several ranks the pressure is solved by hypre, which has "
                                   "no {}: choose one of {}",
                                   parameters.solver, fmt::join(split, ", ")));
    }
  }
  refuse_device_with_open_water(config, parameters.emulated_device);
  auto model = std::make_unique<MpsModel<D>>(parameters, config, bodies, ranks);
  // Split before the first neighbour list, which each rank then builds over its own particles
  // and its ghosts: two neighbour radii of them (a ghost's number density, its surface and its
  // row number are read where it is a neighbour, and they come from its own neighbours); a
  // periodic side's images likewise.
  model->distribute(ranks, 2 * model->interaction_radius());
  model->initialize();
  return model;
}

}  // namespace

template <int D>
ModelEntry mps_entry() {
  ModelEntry entry;
  entry.make = make_mps<D>;
  entry.size.bytes_per_element = 800;  // measured: docs/output.md
  // On the emulated device, with the neighbour list (docs/performance.md).
  entry.size.device_bytes_per_element = [](int dimension) { return dimension == 2 ? 544 : 728; };
  entry.devices = {"cpu", "emulated"};
  entry.one_rank_only.clear();
  entry.open_boundaries = true;
  entry.periodic = true;
  entry.damping_zones = true;
  return entry;
}

template ModelEntry mps_entry<2>();
template ModelEntry mps_entry<3>();

}  // namespace sluice
