// Wall boundary particles after Adami, Hu & Adams (2012): each wall particle takes the pressure
// of the fluid around it, with the hydrostatic correction for the wall's own acceleration, the
// density of that pressure by the equation of state, and, for no-slip, a viscous velocity that
// mirrors the fluid's Shepard-averaged velocity about the wall's own. The fluid then sees walls
// through its ordinary momentum equation, with no gap at the wall.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "sluice/exec/policy.hpp"
#include "sluice/fluid/particle_state.hpp"
#include "sluice/fluid/wcsph/packed_particles.hpp"
#include "sluice/fluid/wcsph/tait.hpp"

namespace sluice {

struct AdamiWallSums {
  double weight = 0, pressure = 0;
  std::array<double, 3> rho_r{}, velocity{};
};

// Kernel-weighted sums over the fluid particles in [begin, end) around wall particle w, as SIMD.
template <class Kernel>
void add_adami_wall_sums(const PackedParticles& packed, const Kernel& kernel, std::size_t w,
                         std::uint32_t begin, std::uint32_t end, AdamiWallSums& out) {
  const auto p = packed.view();
  const float xw = p.x[w], yw = p.y[w], zw = p.z[w];
  float sw = 0, sp = 0, srx = 0, sry = 0, srz = 0, svx = 0, svy = 0, svz = 0;
#pragma omp simd reduction(+ : sw, sp, srx, sry, srz, svx, svy, svz)
  for (std::size_t f = begin; f < end; ++f) {
    const float rx = xw - p.x[f], ry = yw - p.y[f], rz = zw - p.z[f];
    const float weight =
        p.fluid[f] * kernel.value_branchless(std::sqrt(rx * rx + ry * ry + rz * rz));
    const float rho_weight = p.density[f] * weight;
    sw += weight;
    sp += p.pressure[f] * weight;
    srx += rho_weight * rx;
    sry += rho_weight * ry;
    srz += rho_weight * rz;
    svx += weight * p.vx[f];
    svy += weight * p.vy[f];
    svz += weight * p.vz[f];
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

// Sets every wall and body particle's pressure, density and viscous velocity (`wall_velocity`)
// from the packed fluid around it.
template <int D, class Kernel>
void update_adami_walls(ParticleState<D>& s, const PackedParticles& packed, const Kernel& kernel,
                        const TaitEquation& eos, std::vector<Vec<D>>& wall_velocity) {
  auto& ps = s.particles;
  const Vec3 g = to_3d<D>(s.gravity);
  exec::Default::for_each_balanced(ps.size(), [&](std::size_t w) {
    if (ps.is_fluid(w)) return;
    AdamiWallSums sums;
    s.cells.for_each_candidate_range(ps.position[w], [&](std::uint32_t begin, std::uint32_t end) {
      if (packed.has_fluid(begin, end)) add_adami_wall_sums(packed, kernel, w, begin, end, sums);
    });
    if (sums.weight > 0) {
      // A body's wall feels g - a_wall; a fixed wall does not accelerate.
      Vec3 g_wall = g;
      if (ps.body_point[w] >= 0) g_wall -= s.body_point_acceleration[ps.body_point[w]];
      const Real hydrostatic =
          g_wall[0] * sums.rho_r[0] + g_wall[1] * sums.rho_r[1] + g_wall[2] * sums.rho_r[2];
      const Real p = (sums.pressure + hydrostatic) / sums.weight;
      ps.pressure[w] = p;
      ps.density[w] = eos.density(p);
      const Vec3 mean(sums.velocity[0], sums.velocity[1], sums.velocity[2]);
      wall_velocity[w] = 2 * ps.velocity[w] - from_3d<D>(mean / sums.weight);
    } else {
      ps.pressure[w] = 0;
      ps.density[w] = eos.rho0;
      wall_velocity[w] = ps.velocity[w];
    }
  });
}

}  // namespace sluice
