#include "sluice/fluid/wcsph/wcsph_factory.hpp"

#include "sluice/fluid/wcsph/wcsph_device_run.hpp"
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

template <int D>
std::unique_ptr<FluidSystem> make_wcsph(const io::CaseConfig& config, const BodyGeometry& bodies,
                                        const ModelServices&) {
  const WcsphParameters p = read_wcsph_parameters(config);
  switch (p.kernel) {
    case KernelChoice::kCubicSpline:
      return build<D, CubicSpline<D>>(p, config, bodies);
    case KernelChoice::kWendlandC2:
      break;
  }
  return build<D, WendlandC2<D>>(p, config, bodies);
}

}  // namespace

template <int D>
ModelEntry wcsph_entry() {
  ModelEntry entry;
  entry.make = make_wcsph<D>;
  entry.size.bytes_per_element = 500;  // measured: docs/output.md
  entry.size.device_bytes_per_element = wcsph_device_bytes_per_particle;
  entry.devices = {"cpu", "gpu", "emulated"};
  return entry;
}

template ModelEntry wcsph_entry<2>();
template ModelEntry wcsph_entry<3>();

}  // namespace sluice
