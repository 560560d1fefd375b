// gpu_devices.hpp's questions put to CUDA (built where CMake finds nvcc).
#include <string>

#include "sluice/exec/cuda_backend.cuh"
#include "sluice/exec/gpu_devices.hpp"

namespace sluice::exec {

bool cuda_gpu_found(std::string& why) {
  int count = 0;
  const cudaError_t status = cudaGetDeviceCount(&count);
  if (status != cudaSuccess) {
    why = std::string("no GPU found: ") + cudaGetErrorString(status);
    return false;
  }
  if (count == 0) {
    why = "no GPU found";
    return false;
  }
  return true;
}

DeviceMemory cuda_gpu_memory() {
  std::size_t free = 0, total = 0;
  cuda_check(cudaMemGetInfo(&free, &total), "cudaMemGetInfo");
  return {CudaBackend::name(), static_cast<double>(free)};
}

}  // namespace sluice::exec
