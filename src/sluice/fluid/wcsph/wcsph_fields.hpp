// What a WCSPH loop body reads: the particle fields as plain arrays, on the host (the particle
// set's vectors) or on a device alike, and the model's constants.
#pragma once

#include <cstddef>
#include <cstdint>

#include "sluice/core/host_device.hpp"
#include "sluice/core/types.hpp"
#include "sluice/fluid/wcsph/packed_particles.hpp"
#include "sluice/fluid/wcsph/tait.hpp"
#include "sluice/fluid/wcsph/wcsph_pair_term.hpp"
#include "sluice/neighbor/cell_list.hpp"
#include "sluice/particles/particle_set.hpp"

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

// The fields wcsph adds to the particle set (the engine's are ParticleSet's own).
template <int D>
struct WcsphFieldHandles {
  FieldHandle<Vec<D>> acceleration, half_velocity, wall_velocity;
  FieldHandle<Real> density_rate, half_density;
};
template <int D>
WcsphFieldHandles<D> add_wcsph_fields(ParticleSet<D>& ps) {
  WcsphFieldHandles<D> h;
  h.acceleration = ps.add_vector_field({"acceleration", "m/s^2"});
  h.density_rate = ps.add_scalar_field({"density_rate", "kg/m^3/s"});
  h.half_velocity = ps.add_vector_field({"half_step_velocity", "m/s"});
  h.half_density = ps.add_scalar_field({"half_step_density", "kg/m^3"});
  // Walls: the velocity the viscous terms see (no-slip: mirrored about the wall's own).
  h.wall_velocity = ps.add_vector_field({"wall_velocity", "m/s"});
  return h;
}

// The fields of a set with wcsph's fields, on the host (a ParticleSet) or on a device (a
// DeviceParticleSet) alike, found by their names; and the body points' accelerations (3 reals
// a point), which are not particle fields.
template <int D, class Set>
WcsphFields<D> wcsph_fields(Set& set, const Real* body_point_acceleration) {
  WcsphFields<D> f;
  f.size = set.size();
  f.position = set.template components<Real>("position");
  f.velocity = set.template components<Real>("velocity");
  f.density = set.template components<Real>("density");
  f.pressure = set.template components<Real>("pressure");
  f.mass = set.template components<Real>("mass");
  f.kind = set.template components<std::int32_t>("kind");
  f.body_point = set.template components<std::int32_t>("body_point");
  f.acceleration = set.template components<Real>("acceleration");
  f.density_rate = set.template components<Real>("density_rate");
  f.half_velocity = set.template components<Real>("half_step_velocity");
  f.half_density = set.template components<Real>("half_step_density");
  f.wall_velocity = set.template components<Real>("wall_velocity");
  f.body_point_acceleration = body_point_acceleration;
  return f;
}

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
