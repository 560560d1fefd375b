#include "sluice/fluid/constraint/constraint_factory.hpp"

#include "sluice/fluid/constraint/constraint_model.hpp"

namespace sluice {

template <int D>
std::unique_ptr<FluidSystem> make_constraint(const io::CaseConfig& config,
                                             const BodyGeometry& bodies) {
  auto model =
      std::make_unique<ConstraintModel<D>>(read_constraint_parameters(config), config, bodies);
  model->initialize();
  return model;
}

template std::unique_ptr<FluidSystem> make_constraint<2>(const io::CaseConfig&,
                                                         const BodyGeometry&);
template std::unique_ptr<FluidSystem> make_constraint<3>(const io::CaseConfig&,
                                                         const BodyGeometry&);

}  // namespace sluice
