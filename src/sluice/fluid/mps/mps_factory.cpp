#include "sluice/fluid/mps/mps_factory.hpp"

#include "sluice/fluid/mps/mps_model.hpp"

namespace sluice {

namespace {

template <int D>
std::unique_ptr<FluidSystem> make_mps(const io::CaseConfig& config, const BodyGeometry& bodies,
                                      const ModelServices& services) {
  MpsParameters parameters = read_mps_parameters(config);
  parameters.solver_settings.hypre = services.hypre;
  auto model = std::make_unique<MpsModel<D>>(parameters, config, bodies);
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
  return entry;
}

template ModelEntry mps_entry<2>();
template ModelEntry mps_entry<3>();

}  // namespace sluice
