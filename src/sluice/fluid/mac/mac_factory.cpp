#include "sluice/fluid/mac/mac_factory.hpp"

#include "sluice/fluid/mac/mac_model.hpp"

namespace sluice {

template <int D>
std::unique_ptr<FluidSystem> make_mac(const io::CaseConfig& config, const BodyGeometry& bodies) {
  return std::make_unique<MacModel<D>>(read_mac_parameters(config), config, bodies);
}

template std::unique_ptr<FluidSystem> make_mac<2>(const io::CaseConfig&, const BodyGeometry&);
template std::unique_ptr<FluidSystem> make_mac<3>(const io::CaseConfig&, const BodyGeometry&);

}  // namespace sluice
