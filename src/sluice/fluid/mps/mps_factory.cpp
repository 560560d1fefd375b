#include "sluice/fluid/mps/mps_factory.hpp"

#include "sluice/fluid/mps/mps_model.hpp"

namespace sluice {

template <int D>
std::unique_ptr<FluidSystem> make_mps(const io::CaseConfig& config, const BodyGeometry& bodies) {
  auto model = std::make_unique<MpsModel<D>>(read_mps_parameters(config), config, bodies);
  model->initialize();
  return model;
}

template std::unique_ptr<FluidSystem> make_mps<2>(const io::CaseConfig&, const BodyGeometry&);
template std::unique_ptr<FluidSystem> make_mps<3>(const io::CaseConfig&, const BodyGeometry&);

}  // namespace sluice
