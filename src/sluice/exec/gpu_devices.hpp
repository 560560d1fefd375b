// Whether this build and machine have a GPU to run on, and how much of its memory is free: for
// the models' device runs to refuse a GPU that is not there, and for the size estimate to
// refuse a case that cannot fit in it, before anything is built.
#pragma once

#include <string>

namespace sluice::exec {

// Whether a GPU can run here; when not, `why` says what is missing (a build without CUDA, no
// GPU found).
bool gpu_available(std::string& why);

// A device's name and the memory it has free.
struct DeviceMemory {
  std::string name;
  double free_bytes = 0;  // 0: unknown
};

// The GPU's, as CUDA reports it; {"GPU", 0} where there is none.
DeviceMemory gpu_memory();

}  // namespace sluice::exec
