// Wall boundary particles after Adami, Hu & Adams (2012): each wall particle takes the pressure
// of the fluid around it, with the hydrostatic correction for the wall's own acceleration, the
// density of that pressure by the equation of state, and, for no-slip, a viscous velocity that
// mirrors the fluid's Shepard-averaged velocity about the wall's own. The fluid then sees walls
// through its ordinary momentum equation, with no gap at the wall. The loop body serves the
// host and the device (wcsph_loop_bodies.hpp).
#pragma once

#include <cmath>
#include <cstdint>

#include "sluice/core/host_device.hpp"
#include "sluice/fluid/wcsph/packed_particles.hpp"
#include "sluice/fluid/wcsph/wcsph_fields.hpp"
#include "sluice/neighbor/cell_list.hpp"

namespace sluice {

// Kernel-weighted sums over the fluid particles [begin, end) of the fluid's own arrays (the
// fluid particles alone, PackedParticles::fluid_position ...) around wall particle w.
struct AdamiWallSums {
  double weight = 0, pressure = 0;
  double rho_r[3] = {0, 0, 0}, velocity[3] = {0, 0, 0};
};

// `p` by value, as a local copy, as the rates' loop reads it.
template <class Kernel>
SLUICE_HOST_DEVICE inline void add_adami_wall_sums(const PackedParticles::View p,
                                                   const Kernel& kernel, std::size_t w,
                                                   std::uint32_t begin, std::uint32_t end,
                                                   AdamiWallSums& out) {
  const float xw = p.x[w], yw = p.y[w], zw = p.z[w];
  float sw = 0, sp = 0, srx = 0, sry = 0, srz = 0, svx = 0, svy = 0, svz = 0;
#if !defined(__CUDACC__)
#pragma omp simd reduction(+ : sw, sp, srx, sry, srz, svx, svy, svz)
#endif
  for (std::size_t f = begin; f < end; ++f) {
    const float rx = xw - p.fluid_x[f], ry = yw - p.fluid_y[f], rz = zw - p.fluid_z[f];
    const float weight = kernel.value_branchless(std::sqrt(rx * rx + ry * ry + rz * rz));
    const float rho_weight = p.fluid_density[f] * weight;
    sw += weight;
    sp += p.fluid_pressure[f] * weight;
    srx += rho_weight * rx;
    sry += rho_weight * ry;
    srz += rho_weight * rz;
    svx += weight * p.fluid_vx[f];
    svy += weight * p.fluid_vy[f];
    svz += weight * p.fluid_vz[f];
  }
  out.weight += sw;
  out.pressure += sp;
  out.rho_r[0] += srx;
  out.rho_r[1] += sry;
  out.rho_r[2] += srz;
  out.velocity[0] += svx;
  out.velocity[1] += svy;
  out.velocity[2] += svz;
}

// A wall or body particle takes the pressure of the fluid around it, corrected for its own
// acceleration (a body's wall feels g - a_wall), the density of that pressure, and for the
// viscous terms the fluid's Shepard-averaged velocity mirrored about its own (Adami et al.).
template <int D, class Kernel>
struct AdamiWall {
  WcsphNeighbourhood<D, Kernel> n;
  SLUICE_HOST_DEVICE void operator()(std::size_t w) const {
    const auto& [f, packed, cells, c] = n;
    if (f.fluid(w)) return;
    AdamiWallSums sums;
    // Most wall particles have no fluid in the cells around them: a look at the whole rows
    // (no square roots) skips them before the clipped ranges are worked out.
    bool wet = false;
    cells.for_each_candidate_range(f.position + D * w, [&](std::uint32_t begin, std::uint32_t end) {
      wet = wet || packed.has_fluid(begin, end);
    });
    if (wet) {
      // A range of the particles holds the fluid particles [fluid_before[begin],
      // fluid_before[end]) of the fluid's own arrays, in the same order.
      cells.for_each_clipped_range(f.position + D * w, [&](std::uint32_t begin, std::uint32_t end) {
        if (packed.has_fluid(begin, end)) {
          add_adami_wall_sums(packed, c.kernel, w, packed.fluid_before[begin],
                              packed.fluid_before[end], sums);
        }
      });
    }
    if (sums.weight > 0) {
      Real g_wall[3] = {c.gravity[0], c.gravity[1], c.gravity[2]};
      if (f.body_point[w] >= 0) {
        const Real* a = f.body_point_acceleration + 3 * f.body_point[w];
        for (int k = 0; k < 3; ++k) g_wall[k] -= a[k];
      }
      const Real hydrostatic =
          g_wall[0] * sums.rho_r[0] + g_wall[1] * sums.rho_r[1] + g_wall[2] * sums.rho_r[2];
      // A fluid whose tension is clamped does not pull on its walls either.
      const Real extrapolated = (sums.pressure + hydrostatic) / sums.weight;
      const Real p = extrapolated > c.eos.lowest ? extrapolated : c.eos.lowest;
      f.pressure[w] = p;
      f.density[w] = c.eos.density(p);
      for (int a = 0; a < D; ++a) {
        const Real mean = sums.velocity[D == 3 ? a : 2 * a] / sums.weight;
        f.wall_velocity[D * w + a] = 2 * f.velocity[D * w + a] - mean;
      }
    } else {
      f.pressure[w] = 0;
      f.density[w] = c.eos.rho0;
      for (int a = 0; a < D; ++a) f.wall_velocity[D * w + a] = f.velocity[D * w + a];
    }
  }
};

}  // namespace sluice
