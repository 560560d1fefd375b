// A single-precision structure-of-arrays copy of what the WCSPH pair loops read, refreshed
// once per step. One array per component lets the compiler run the loops over a contiguous
// range of neighbours as SIMD; single precision halves the memory traffic (positions are
// packed relative to nothing larger than the domain, so float keeps sub-micrometre detail for
// domains of a few metres).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "sluice/core/host_device.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

// Always three components; 2D models (x-z plane) have y = 0, so one SIMD loop serves both.
struct PackedParticles {
  std::array<std::vector<float>, 3> position;
  std::array<std::vector<float>, 3> velocity;          // own velocity (walls: the wall's)
  std::array<std::vector<float>, 3> viscous_velocity;  // walls: the no-slip mirror velocity
  std::vector<float> density;
  std::vector<float> pressure;
  std::vector<float> pressure_term;         // p / rho^2
  std::vector<float> volume;                // m / rho
  std::vector<float> fluid;                 // 1 for fluid, 0 for boundary particles
  std::vector<float> viscous_weight;        // 1 where viscosity acts on the pair partner, else 0
  std::vector<std::uint32_t> fluid_before;  // fluid particles among indices [0, k); size n + 1
  // The fluid particles alone, in index order (fluid particle i at fluid_before[i]): what the
  // walls' loop reads, so that its candidates hold no wall particle, which would add nothing.
  std::array<std::vector<float>, 3> fluid_position, fluid_velocity;
  std::vector<float> fluid_density, fluid_pressure;

  // Raw pointers for the SIMD loops (they only read, so aliasing does not matter).
  struct View {
    const float *x, *y, *z, *vx, *vy, *vz, *wx, *wy, *wz;
    const float *density, *pressure, *pressure_term, *volume, *fluid, *viscous_weight;
    const std::uint32_t* fluid_before;
    const float *fluid_x, *fluid_y, *fluid_z, *fluid_vx, *fluid_vy, *fluid_vz;
    const float *fluid_density, *fluid_pressure;
    SLUICE_HOST_DEVICE bool has_fluid(std::uint32_t begin, std::uint32_t end) const {
      return fluid_before[end] != fluid_before[begin];
    }
  };
  // The same arrays to write, wherever they live (the host's vectors here; a device's copy).
  struct Arrays {
    float* position[3];
    float* velocity[3];
    float* viscous_velocity[3];
    float *density, *pressure, *pressure_term, *volume, *fluid, *viscous_weight;
    std::uint32_t* fluid_before;
    float* fluid_position[3];
    float* fluid_velocity[3];
    float *fluid_density, *fluid_pressure;
    View view() const {
      return {position[0],
              position[1],
              position[2],
              velocity[0],
              velocity[1],
              velocity[2],
              viscous_velocity[0],
              viscous_velocity[1],
              viscous_velocity[2],
              density,
              pressure,
              pressure_term,
              volume,
              fluid,
              viscous_weight,
              fluid_before,
              fluid_position[0],
              fluid_position[1],
              fluid_position[2],
              fluid_velocity[0],
              fluid_velocity[1],
              fluid_velocity[2],
              fluid_density,
              fluid_pressure};
    }
  };
  Arrays arrays() {
    return {{position[0].data(), position[1].data(), position[2].data()},
            {velocity[0].data(), velocity[1].data(), velocity[2].data()},
            {viscous_velocity[0].data(), viscous_velocity[1].data(), viscous_velocity[2].data()},
            density.data(),
            pressure.data(),
            pressure_term.data(),
            volume.data(),
            fluid.data(),
            viscous_weight.data(),
            fluid_before.data(),
            {fluid_position[0].data(), fluid_position[1].data(), fluid_position[2].data()},
            {fluid_velocity[0].data(), fluid_velocity[1].data(), fluid_velocity[2].data()},
            fluid_density.data(),
            fluid_pressure.data()};
  }
  View view() const { return const_cast<PackedParticles*>(this)->arrays().view(); }

  bool has_fluid(std::uint32_t begin, std::uint32_t end) const {
    return fluid_before[end] != fluid_before[begin];
  }

  // For n particles, `fluid` of them fluid.
  void resize(std::size_t n, std::size_t fluid_count) {
    for (int a = 0; a < 3; ++a) {
      position[a].resize(n);
      velocity[a].resize(n);
      viscous_velocity[a].resize(n);
      fluid_position[a].resize(fluid_count);
      fluid_velocity[a].resize(fluid_count);
    }
    fluid_density.resize(fluid_count);
    fluid_pressure.resize(fluid_count);
    for (auto* f : {&density, &pressure, &pressure_term, &volume, &fluid, &viscous_weight}) {
      f->resize(n);
    }
    fluid_before.resize(n + 1);
  }
};

}  // namespace sluice
