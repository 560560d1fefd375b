#include "sluice/fluid/constraint/constraint_factory.hpp"

#include "sluice/fluid/constraint/constraint_model.hpp"
#include "sluice/fluid/constraint/constraint_parameters.hpp"

namespace sluice {

namespace {

template <int D>
std::unique_ptr<FluidSystem> make_constraint(const io::CaseConfig& config,
                                             const BodyGeometry& bodies, const ModelServices&) {
  auto model =
      std::make_unique<ConstraintModel<D>>(read_constraint_parameters(config), config, bodies);
  model->initialize();
  return model;
}

}  // namespace

template <int D>
ModelEntry constraint_entry() {
  ModelEntry entry;
  entry.make = make_constraint<D>;
  entry.prepare = prepare_constraint_case;
  entry.size.bytes_per_element = 6000;  // measured: docs/output.md
  entry.schemes = {"monolithic"};
  // The emulated device's copy of the problem each solve (docs/performance.md).
  entry.size.device_bytes_per_element = [](int dimension) { return dimension == 2 ? 1130 : 1890; };
  entry.devices = {"cpu", "emulated"};
  entry.one_rank_only =
      "its complementarity step solves the fluid and the bodies as one system, not split over "
      "ranks";
  return entry;
}

template ModelEntry constraint_entry<2>();
template ModelEntry constraint_entry<3>();

}  // namespace sluice
