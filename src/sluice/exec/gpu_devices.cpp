#include "sluice/exec/gpu_devices.hpp"

namespace sluice::exec {

#if defined(SLUICE_WITH_CUDA)
// gpu_devices_cuda.cu
bool cuda_gpu_found(std::string& why);
DeviceMemory cuda_gpu_memory();
#endif

bool gpu_available(std::string& why) {
#if defined(SLUICE_WITH_CUDA)
  return cuda_gpu_found(why);
#else
  why = "this sluice was built without CUDA (nvcc was not found when it was configured)";
  return false;
#endif
}

DeviceMemory gpu_memory() {
#if defined(SLUICE_WITH_CUDA)
  std::string why;
  if (cuda_gpu_found(why)) return cuda_gpu_memory();
#endif
  return {"GPU", 0};
}

}  // namespace sluice::exec
