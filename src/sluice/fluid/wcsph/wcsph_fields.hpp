// What a WCSPH loop body reads: the particle fields as plain arrays, on the host (the particle
// set's vectors) or on a device alike, and the model's constants.
#pragma once

#include <cstddef>
#include <cstdint>

#include "sluice/core/types.hpp"
#include "sluice/exec/host_device.hpp"
#include "sluice/fluid/wcsph/packed_particles.hpp"
#include "sluice/fluid/wcsph/tait.hpp"
#include "sluice/fluid/wcsph/wcsph_pair_term.hpp"
#include "sluice/neighbor/cell_list.hpp"

namespace sluice {

// The particle fields a WCSPH step reads and writes. A vector field holds D reals per particle;
// kind is ParticleKind's integer (0 is fluid); body_point_acceleration holds 3 reals per body
// point.
template <int D>
struct WcsphFields {
  std::size_t size = 0;
  Real* position = nullptr;
  Real* velocity = nullptr;
  Real* density = nullptr;
  Real* pressure = nullptr;
  const Real* mass = nullptr;
  const std::int32_t* kind = nullptr;
  const std::int32_t* body_point = nullptr;
  Real* acceleration = nullptr;
  Real* density_rate = nullptr;
  Real* half_velocity = nullptr;
  Real* half_density = nullptr;
  Real* wall_velocity = nullptr;
  const Real* body_point_acceleration = nullptr;

  SLUICE_HOST_DEVICE bool fluid(std::size_t i) const { return kind[i] == 0; }
};

// The constants of the loop bodies, from the model's parameters and the case.
template <int D, class Kernel>
struct WcsphConstants {
  Kernel kernel;
  TaitEquation eos;
  WcsphPairConstants pair;
  Real gravity[3] = {0, 0, 0};  // 3D (2D: x, 0, z)
  Real two_nu_rho0 = 0;         // 2 nu rho0, the laminar viscosity's numerator
  bool no_slip = true;
};

// What a loop over a particle's neighbours reads: the fields, their packed single-precision
// copy, the cells and the constants.
template <int D, class Kernel>
struct WcsphNeighbourhood {
  WcsphFields<D> f;
  PackedParticles::View packed;
  CellGridView<D> cells;
  WcsphConstants<D, Kernel> c;
};

}  // namespace sluice
