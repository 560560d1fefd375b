// SLUICE_HOST_DEVICE marks what the CUDA policy runs on the device as well as on the host: the
// loop bodies and the small functions they call (kernels, equation of state, pair terms). Under
// the host compiler it is nothing; under nvcc it is __host__ __device__.
#pragma once

#if defined(__CUDACC__)
#define SLUICE_HOST_DEVICE __host__ __device__
#else
#define SLUICE_HOST_DEVICE
#endif

// SLUICE_ONE_HOST_COPY marks a function whose answer the host's own path and the emulated device
// run must share to the bit: compiled on its own, not into each caller's loop, where the
// compiler may fuse its multiplies and adds into different FMAs. (The device's copy is its own.)
#if defined(__CUDA_ARCH__)
#define SLUICE_ONE_HOST_COPY
#else
#define SLUICE_ONE_HOST_COPY __attribute__((noinline))
#endif
