// SLUICE_HOST_DEVICE marks what the CUDA policy runs on the device as well as on the host: the
// loop bodies and the small functions they call (kernels, equation of state, pair terms). Under
// the host compiler it is nothing; under nvcc it is __host__ __device__.
#pragma once

#if defined(__CUDACC__)
#define SLUICE_HOST_DEVICE __host__ __device__
#else
#define SLUICE_HOST_DEVICE
#endif
