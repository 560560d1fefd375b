#include "sluice/fluid/granular/granular_factory.hpp"

#include "sluice/fluid/granular/granular_model.hpp"

namespace sluice {

template <int D>
std::unique_ptr<FluidSystem> make_granular(const io::CaseConfig& config,
                                           const BodyGeometry& bodies) {
  auto model = std::make_unique<GranularModel<D>>(read_granular_parameters(config), config, bodies);
  model->initialize();
  return model;
}

template std::unique_ptr<FluidSystem> make_granular<2>(const io::CaseConfig&, const BodyGeometry&);
template std::unique_ptr<FluidSystem> make_granular<3>(const io::CaseConfig&, const BodyGeometry&);

}  // namespace sluice
