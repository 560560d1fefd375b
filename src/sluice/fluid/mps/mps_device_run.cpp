// The device runs mps offers: the host-threads one (the emulated device). A GPU's needs the
// pressure solve there too (issue 41); until then `model.device` offers cpu and emulated.
#include "sluice/fluid/mps/mps_device_run.hpp"

#include "sluice/exec/host_backend.hpp"
#include "sluice/fluid/mps/mps_device_run_impl.hpp"

namespace sluice {

template <int D>
std::unique_ptr<MpsDeviceRun<D>> make_mps_emulated_run(const MpsDeviceSetup<D>& setup) {
  return std::make_unique<MpsDeviceRunOn<D, exec::HostBackend>>(setup);
}

template std::unique_ptr<MpsDeviceRun<2>> make_mps_emulated_run(const MpsDeviceSetup<2>&);
template std::unique_ptr<MpsDeviceRun<3>> make_mps_emulated_run(const MpsDeviceSetup<3>&);

}  // namespace sluice
