// A check of the CUDA backend's own pieces against the host's answers (arrays to and from the
// device, a loop, the stable sort, the scan, the largest value), for the GPU checks to run
// before the physics: what fails here is the backend, not a model. Built with the CUDA policy.
#pragma once

#include <string>

namespace sluice::exec {

// What disagreed with the host, one line each; empty when everything agreed. `n` values.
std::string check_cuda_backend(std::size_t n);

}  // namespace sluice::exec
