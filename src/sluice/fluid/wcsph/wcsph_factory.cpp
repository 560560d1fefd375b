#include "sluice/fluid/wcsph/wcsph_factory.hpp"

#include "sluice/core/errors.hpp"
#include "sluice/fluid/wcsph/wcsph_device_run.hpp"
#include "sluice/fluid/wcsph/wcsph_model.hpp"
#include "sluice/kernels/cubic_spline.hpp"
#include "sluice/kernels/wendland_c2.hpp"

namespace sluice {

namespace {
template <int D, class Kernel>
std::unique_ptr<FluidSystem> build(const WcsphParameters& p, const io::CaseConfig& config,
                                   const BodyGeometry& bodies, const ModelServices& services) {
  refuse_device_with_open_water(config, p.device != WcsphDevice::kCpu);
  auto model = std::make_unique<WcsphModel<D, Kernel>>(p, config, bodies);
  if (services.split() && p.device != WcsphDevice::kCpu) {
    throw InputError(config.file(), config.model_line, "model.device",
                     "a run on several ranks runs on the CPU for now (device: cpu)");
  }
  // A ghost wall's pressure comes from the fluid within a support of it, which a fluid
  // particle a support inside the slab reads: two supports of ghosts (a periodic side's images
  // too). Split before the model's first rates, which it then works out over the rank's own
  // particles and ghosts.
  model->distribute(services.split() ? *services.ranks : Communicator::alone(),
                    2 * model->interaction_radius());
  model->initialize();
  return model;
}

template <int D>
std::unique_ptr<FluidSystem> make_wcsph(const io::CaseConfig& config, const BodyGeometry& bodies,
                                        const ModelServices& services) {
  const WcsphParameters p = read_wcsph_parameters(config);
  switch (p.kernel) {
    case KernelChoice::kCubicSpline:
      return build<D, CubicSpline<D>>(p, config, bodies, services);
    case KernelChoice::kWendlandC2:
      break;
  }
  return build<D, WendlandC2<D>>(p, config, bodies, services);
}

}  // namespace

template <int D>
ModelEntry wcsph_entry() {
  ModelEntry entry;
  entry.make = make_wcsph<D>;
  entry.size.bytes_per_element = 500;  // measured: docs/output.md
  entry.size.device_bytes_per_element = wcsph_device_bytes_per_particle;
  entry.devices = {"cpu", "gpu", "emulated"};
  entry.one_rank_only.clear();
  entry.open_boundaries = true;
  entry.periodic = true;
  entry.damping_zones = true;
  return entry;
}

template ModelEntry wcsph_entry<2>();
template ModelEntry wcsph_entry<3>();

}  // namespace sluice
