#include "sluice/fluid/wcsph/wcsph_factory.hpp"

#include "sluice/fluid/wcsph/wcsph_model.hpp"
#include "sluice/kernels/cubic_spline.hpp"
#include "sluice/kernels/wendland_c2.hpp"

namespace sluice {

namespace {
template <int D, class Kernel>
std::unique_ptr<FluidSystem> build(const WcsphParameters& p, const io::CaseConfig& config,
                                   const BodyGeometry& bodies) {
  auto model = std::make_unique<WcsphModel<D, Kernel>>(p, config, bodies);
  model->initialize();
  return model;
}
}  // namespace

template <int D>
std::unique_ptr<FluidSystem> make_wcsph(const io::CaseConfig& config, const BodyGeometry& bodies) {
  const WcsphParameters p = read_wcsph_parameters(config);
  switch (p.kernel) {
    case KernelChoice::kCubicSpline:
      return build<D, CubicSpline<D>>(p, config, bodies);
    case KernelChoice::kWendlandC2:
      break;
  }
  return build<D, WendlandC2<D>>(p, config, bodies);
}

template std::unique_ptr<FluidSystem> make_wcsph<2>(const io::CaseConfig&, const BodyGeometry&);
template std::unique_ptr<FluidSystem> make_wcsph<3>(const io::CaseConfig&, const BodyGeometry&);

}  // namespace sluice
