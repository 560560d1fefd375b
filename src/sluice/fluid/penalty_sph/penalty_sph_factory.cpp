#include "sluice/fluid/penalty_sph/penalty_sph_factory.hpp"

#include "sluice/core/errors.hpp"

#include "sluice/fluid/penalty_sph/penalty_sph_model.hpp"
#include "sluice/fluid/penalty_sph/penalty_sph_parameters.hpp"

namespace sluice {

namespace {

template <int D>
std::unique_ptr<FluidSystem> make_penalty_sph(const io::CaseConfig& config,
                                              const BodyGeometry& bodies,
                                              const ModelServices& services) {
  const PenaltySphParameters p = read_penalty_sph_parameters(config);
  refuse_device_with_open_water(config, p.emulated_device);
  auto model = std::make_unique<PenaltySphModel<D>>(p, config, bodies);
  if (services.split()) {
    if (p.emulated_device) {
      throw InputError(config.file(), config.model_line, "model.device",
                       "a run on several ranks runs on the CPU for now (device: cpu)");
    }
    model->split_over(*services.ranks);
  }
  model->initialize();
  return model;
}

}  // namespace

template <int D>
ModelEntry penalty_sph_entry() {
  ModelEntry entry;
  entry.make = make_penalty_sph<D>;
  entry.prepare = [](io::CaseConfig& config) {
    for (io::BodyConfig& b : free_solid_grains(config)) config.bodies.push_back(std::move(b));
  };
  entry.size.bytes_per_element = 550;  // measured: docs/output.md
  // On the emulated device (docs/performance.md).
  entry.size.device_bytes_per_element = [](int dimension) { return dimension == 2 ? 404 : 508; };
  entry.schemes = {"spring-exchanges"};
  entry.devices = {"cpu", "emulated"};
  entry.one_rank_only.clear();
  entry.periodic = true;
  entry.damping_zones = true;
  return entry;
}

template ModelEntry penalty_sph_entry<2>();
template ModelEntry penalty_sph_entry<3>();

}  // namespace sluice
