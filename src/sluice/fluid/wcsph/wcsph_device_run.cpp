// The device runs this build offers: the host-threads one always, the CUDA one where the build
// found nvcc (SLUICE_WITH_CUDA; wcsph_device_cuda.cu).
#include "sluice/fluid/wcsph/wcsph_device_run.hpp"

#include <stdexcept>

#include "sluice/exec/gpu_devices.hpp"
#include "sluice/exec/host_backend.hpp"
#include "sluice/fluid/wcsph/wcsph_device_run_impl.hpp"
#include "sluice/kernels/cubic_spline.hpp"
#include "sluice/kernels/wendland_c2.hpp"

namespace sluice {

#if defined(SLUICE_WITH_CUDA)
// wcsph_device_cuda.cu
template <int D, class Kernel>
std::unique_ptr<WcsphDeviceRun<D>> make_wcsph_cuda_run(const WcsphDeviceSetup<D, Kernel>& setup);
#endif

bool wcsph_device_available(WcsphDevice device, std::string& why) {
  return device != WcsphDevice::kGpu || exec::gpu_available(why);
}

double wcsph_device_bytes_per_particle(int dimension) {
  // The same on every backend; the host's names one.
  auto with_wcsph_fields = [](auto layout) {
    add_wcsph_fields(layout);
    return wcsph_device_run_bytes_per_particle<decltype(layout)::kDimension, exec::HostBackend>(
        layout);
  };
  return dimension == 2 ? with_wcsph_fields(ParticleSet<2>()) : with_wcsph_fields(ParticleSet<3>());
}

template <int D, class Kernel>
std::unique_ptr<WcsphDeviceRun<D>> make_wcsph_device_run(WcsphDevice device,
                                                         const WcsphDeviceSetup<D, Kernel>& setup) {
  switch (device) {
    case WcsphDevice::kEmulated:
      return std::make_unique<WcsphDeviceRunOn<D, Kernel, exec::HostBackend>>(setup);
    case WcsphDevice::kGpu: {
      std::string why;
      if (!wcsph_device_available(device, why)) throw std::runtime_error(why);
#if defined(SLUICE_WITH_CUDA)
      return make_wcsph_cuda_run<D, Kernel>(setup);
#else
      break;
#endif
    }
    case WcsphDevice::kCpu:
      break;
  }
  throw std::logic_error("make_wcsph_device_run: the CPU runs on the model's own arrays");
}

#define SLUICE_DEVICE_RUN(D, KERNEL)                                 \
  template std::unique_ptr<WcsphDeviceRun<D>> make_wcsph_device_run( \
      WcsphDevice, const WcsphDeviceSetup<D, KERNEL<D>>&);
SLUICE_DEVICE_RUN(2, WendlandC2)
SLUICE_DEVICE_RUN(3, WendlandC2)
SLUICE_DEVICE_RUN(2, CubicSpline)
SLUICE_DEVICE_RUN(3, CubicSpline)
#undef SLUICE_DEVICE_RUN

}  // namespace sluice
