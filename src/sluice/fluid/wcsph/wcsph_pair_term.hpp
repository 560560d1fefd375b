// The WCSPH pair term (Monaghan 1992): what partner j adds to particle i's acceleration and
// density rate. Continuity m_j v_ij . grad W with Molteni & Colagrossi (2009) density diffusion,
// its hydrostatic part removed (Fourtakas et al. 2019); the pressure gradient
// -m_j (p_i / rho_i^2 + p_j / rho_j^2) grad W; Monaghan's artificial viscosity while the pair
// approaches; Morris's laminar viscosity. One function serves the fluid's own sums and the
// fluid's force on body particles, so the two are equal and opposite by construction.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "sluice/core/host_device.hpp"
#include "sluice/fluid/wcsph/packed_particles.hpp"

namespace sluice {

struct WcsphPairConstants {
  float eta2 = 0, two_alpha_c0_h = 0, diffusion = 0;
  std::array<float, 3> hydrostatic{};  // rho_H_ji = hydrostatic . r_ij
};

// What the pair term reads of particle i itself, in the precision T it is evaluated in.
template <class T>
struct WcsphOwnParticle {
  T x, y, z, vx, vy, vz, rho, pressure_term;
  T laminar;  // 2 nu rho0 / rho_i
};

template <class T>
SLUICE_HOST_DEVICE WcsphOwnParticle<T> own_particle(const PackedParticles::View& p, std::size_t i,
                                                    T laminar) {
  return {p.x[i], p.y[i], p.z[i], p.vx[i], p.vy[i], p.vz[i], p.density[i], p.pressure_term[i],
          laminar};
}

// Adds partner j's term to i's acceleration (ax, ay, az) and density rate, without branches:
// the kernel vanishes beyond its support, and i itself adds exactly zero (every term carries
// r_ij or rho_j - rho_i), so a loop over a whole candidate range runs as SIMD. T is float in
// the fluid's loops; the force on a body particle, a sum over many fluid particles that moves
// a body, is evaluated in double from the same inputs.
template <class T, class Kernel>
SLUICE_HOST_DEVICE inline void add_wcsph_pair_term(const PackedParticles::View& p,
                                                   const WcsphOwnParticle<T>& i, std::size_t j,
                                                   const WcsphPairConstants& k,
                                                   const Kernel& kernel, T& ax, T& ay, T& az,
                                                   T& drho) {
  const T rx = i.x - p.x[j], ry = i.y - p.y[j], rz = i.z - p.z[j];
  const T r2 = rx * rx + ry * ry + rz * rz;
  const T v_dot_r = (i.vx - p.vx[j]) * rx + (i.vy - p.vy[j]) * ry + (i.vz - p.vz[j]) * rz;
  const T ux = i.vx - p.wx[j], uy = i.vy - p.wy[j], uz = i.vz - p.wz[j];  // viscous v_ij
  const T u_dot_r = ux * rx + uy * ry + uz * rz;
  const T f = kernel.gradient_factor_branchless(static_cast<float>(std::sqrt(r2)));
  const T volume_j = p.volume[j];
  const T rho_j = p.density[j];
  const T inverse_r2 = T(1) / (r2 + k.eta2);
  const T hydro = k.hydrostatic[0] * rx + k.hydrostatic[1] * ry + k.hydrostatic[2] * rz;
  drho += rho_j * volume_j * f * v_dot_r  // m_j v_ij . grad W
          + p.fluid[j] * k.diffusion * (rho_j - i.rho - hydro) * f * volume_j;
  // Monaghan's Pi_ij, acting only while the particles approach.
  const T artificial = -k.two_alpha_c0_h * std::min(u_dot_r, T(0)) * inverse_r2 / (i.rho + rho_j);
  const T push = rho_j * volume_j *
                 (i.pressure_term + p.pressure_term[j] + p.viscous_weight[j] * artificial) * f;
  const T laminar = p.viscous_weight[j] * volume_j * i.laminar * r2 * f * inverse_r2;
  ax += laminar * ux - push * rx;
  ay += laminar * uy - push * ry;
  az += laminar * uz - push * rz;
}

}  // namespace sluice
