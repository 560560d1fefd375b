// The transport velocity of Adami, Hu & Adams (2013, J. Comput. Phys. 241, "A transport-velocity
// formulation for smoothed particle hydrodynamics"): particles drift with their velocity plus
// half a step of the acceleration that a uniform background pressure p_b alone would give them,
//   b_i = -(p_b / m_i) sum_j (V_i^2 + V_j^2) grad W_ij,
// which is zero where the particles lie evenly and pushes them apart where they bunch, so that
// a confined flow keeps an even distribution where free-surface SPH's would open voids (the
// tensile instability). The momentum equation is left as it is (their extra stress term, of
// order u (u~ - u), is not added), as particle shifting does (Lind et al. 2012), and so is the
// density's continuity equation (their density is a kernel sum, which, tried on Schäfer &
// Turek's cylinder, left the drag oscillating with the channel's acoustic mode). Only for flows
// without a free surface: there b pushes the surface's particles outwards.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "sluice/core/host_device.hpp"
#include "sluice/fluid/wcsph/wcsph_fields.hpp"
#include "sluice/fluid/wcsph/wcsph_loop_bodies.hpp"

namespace sluice {

// b_i of fluid particle i into background_acceleration (D reals a particle), over all its
// neighbours (fluid, walls, bodies and open boundaries' buffers alike), from the packed copy.
template <int D, class Kernel>
struct WcsphBackgroundAcceleration {
  WcsphNeighbourhood<D, Kernel> n;
  Real background_pressure;
  Real* background_acceleration;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    const auto& [f, packed, cells, c] = n;
    if (!f.fluid(i)) return;
    const float xi = packed.x[i], yi = packed.y[i], zi = packed.z[i];
    const float volume_i2 = packed.volume[i] * packed.volume[i];
    double sum[3] = {0, 0, 0};
    // As the rates' loop: each candidate range in single precision (SIMD on the host, widened
    // to whole vectors: a particle beyond the support adds exactly zero, and i itself too).
    cells.template for_each_clipped_range<kRatesRangeMultiple>(
        f.position + D * i, [&](std::uint32_t begin, std::uint32_t end) {
          const PackedParticles::View p = packed;
          float sx = 0, sy = 0, sz = 0;
#if !defined(__CUDACC__)
#pragma omp simd reduction(+ : sx, sy, sz)
#endif
          for (std::size_t j = begin; j < end; ++j) {
            const float rx = xi - p.x[j], ry = yi - p.y[j], rz = zi - p.z[j];
            const float r = std::sqrt(rx * rx + ry * ry + rz * rz);
            const float weight =
                (volume_i2 + p.volume[j] * p.volume[j]) * c.kernel.gradient_factor_branchless(r);
            sx += weight * rx;
            sy += weight * ry;
            sz += weight * rz;
          }
          sum[0] += sx;
          sum[1] += sy;
          sum[2] += sz;
        });
    const Real scale = -background_pressure / f.mass[i];
    for (int a = 0; a < D; ++a)
      background_acceleration[D * i + a] = scale * sum[D == 3 ? a : 2 * a];
  }
};

}  // namespace sluice
