// The WCSPH device run on a GPU: the run of wcsph_device_run_impl.hpp over the CUDA backend,
// for both dimensions and both kernels. Built where CMake finds nvcc (SLUICE_WITH_CUDA).
#include <string>

#include "sluice/exec/cuda_backend.cuh"
#include "sluice/fluid/wcsph/wcsph_device_run_impl.hpp"
#include "sluice/kernels/cubic_spline.hpp"
#include "sluice/kernels/wendland_c2.hpp"

namespace sluice {

template <int D, class Kernel>
std::unique_ptr<WcsphDeviceRun<D>> make_wcsph_cuda_run(const WcsphDeviceSetup<D, Kernel>& setup) {
  return std::make_unique<WcsphDeviceRunOn<D, Kernel, exec::CudaBackend>>(setup);
}

#define SLUICE_CUDA_RUN(D, KERNEL)                                 \
  template std::unique_ptr<WcsphDeviceRun<D>> make_wcsph_cuda_run( \
      const WcsphDeviceSetup<D, KERNEL<D>>&);
SLUICE_CUDA_RUN(2, WendlandC2)
SLUICE_CUDA_RUN(3, WendlandC2)
SLUICE_CUDA_RUN(2, CubicSpline)
SLUICE_CUDA_RUN(3, CubicSpline)
#undef SLUICE_CUDA_RUN

}  // namespace sluice
