#include "sluice/fluid/penalty_sph/penalty_sph_factory.hpp"

#include "sluice/fluid/penalty_sph/penalty_sph_model.hpp"

namespace sluice {

template <int D>
std::unique_ptr<FluidSystem> make_penalty_sph(const io::CaseConfig& config,
                                              const BodyGeometry& bodies) {
  auto model =
      std::make_unique<PenaltySphModel<D>>(read_penalty_sph_parameters(config), config, bodies);
  model->initialize();
  return model;
}

template std::unique_ptr<FluidSystem> make_penalty_sph<2>(const io::CaseConfig&,
                                                          const BodyGeometry&);
template std::unique_ptr<FluidSystem> make_penalty_sph<3>(const io::CaseConfig&,
                                                          const BodyGeometry&);

}  // namespace sluice
