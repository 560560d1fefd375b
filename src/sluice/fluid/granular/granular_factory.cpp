#include "sluice/fluid/granular/granular_factory.hpp"

#include "sluice/fluid/granular/granular_model.hpp"
#include "sluice/fluid/granular/granular_parameters.hpp"

namespace sluice {

namespace {

template <int D>
std::unique_ptr<FluidSystem> make_granular(const io::CaseConfig& config, const BodyGeometry& bodies,
                                           const ModelServices&) {
  auto model = std::make_unique<GranularModel<D>>(read_granular_parameters(config), config, bodies);
  model->initialize();
  return model;
}

}  // namespace

template <int D>
ModelEntry granular_entry() {
  ModelEntry entry;
  entry.make = make_granular<D>;
  entry.prepare = prepare_granular_case;
  entry.size.bytes_per_element = 900;  // measured: docs/output.md
  entry.schemes = {"monolithic"};
  // The emulated device's copy of the problem each solve (docs/performance.md).
  entry.size.device_bytes_per_element = [](int dimension) { return dimension == 2 ? 510 : 680; };
  entry.devices = {"cpu", "emulated"};
  entry.one_rank_only =
      "its complementarity step solves the spheres and the bodies as one system, not split over "
      "ranks";
  return entry;
}

template ModelEntry granular_entry<2>();
template ModelEntry granular_entry<3>();

}  // namespace sluice
