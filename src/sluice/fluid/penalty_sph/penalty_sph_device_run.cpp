// The device runs penalty-sph offers: the host-threads one (the emulated device).
#include "sluice/fluid/penalty_sph/penalty_sph_device_run.hpp"

#include "sluice/exec/host_backend.hpp"
#include "sluice/fluid/penalty_sph/penalty_sph_device_run_impl.hpp"

namespace sluice {

template <int D>
std::unique_ptr<PenaltySphDeviceRun<D>> make_penalty_sph_emulated_run(
    const PenaltySphDeviceSetup<D>& setup) {
  return std::make_unique<PenaltySphDeviceRunOn<D, exec::HostBackend>>(setup);
}

template std::unique_ptr<PenaltySphDeviceRun<2>> make_penalty_sph_emulated_run(
    const PenaltySphDeviceSetup<2>&);
template std::unique_ptr<PenaltySphDeviceRun<3>> make_penalty_sph_emulated_run(
    const PenaltySphDeviceSetup<3>&);

}  // namespace sluice
