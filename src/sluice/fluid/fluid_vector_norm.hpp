// The length of a fluid particle's vector (its velocity, its acceleration), zero for the other
// particles: the largest of them sets a particle model's time step. A loop body over plain
// arrays, for the host's particle set and a device's copy alike, compiled once on the host, so
// that the host's run and the emulated device's take the same step to the bit.
#pragma once

#include <cstdint>

#include "sluice/core/host_device.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

template <int D>
struct FluidVectorNorm {
  const std::int32_t* kind;  // ParticleKind's integer: 0 is fluid
  const Vec<D>* vector;
  SLUICE_HOST_DEVICE SLUICE_ONE_HOST_COPY double operator()(std::size_t i) const {
    return kind[i] == 0 ? vector[i].norm() : 0.0;
  }
};

}  // namespace sluice
