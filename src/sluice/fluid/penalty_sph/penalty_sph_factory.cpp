#include "sluice/fluid/penalty_sph/penalty_sph_factory.hpp"

#include "sluice/fluid/penalty_sph/penalty_sph_model.hpp"
#include "sluice/fluid/penalty_sph/penalty_sph_parameters.hpp"

namespace sluice {

namespace {

template <int D>
std::unique_ptr<FluidSystem> make_penalty_sph(const io::CaseConfig& config,
                                              const BodyGeometry& bodies, const ModelServices&) {
  auto model =
      std::make_unique<PenaltySphModel<D>>(read_penalty_sph_parameters(config), config, bodies);
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
  return entry;
}

template ModelEntry penalty_sph_entry<2>();
template ModelEntry penalty_sph_entry<3>();

}  // namespace sluice
