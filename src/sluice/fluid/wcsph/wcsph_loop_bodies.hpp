// The loop bodies of a WCSPH step, each a function of one particle's index over plain arrays, so
// that the OpenMP policy runs them on the host's particle set and the CUDA policy on the device's
// copy of it (core/host_device.hpp): kick and drift, packing for the pair loops, the rates and
// the fluid's force on body particles; the walls' state is adami_walls.hpp's. The model
// (wcsph_model.hpp) and the device run (wcsph_device_run.hpp) call these for the physics.
#pragma once

#include <cmath>
#include <cstdint>

#include "sluice/core/host_device.hpp"
#include "sluice/fluid/wcsph/packed_particles.hpp"
#include "sluice/fluid/wcsph/wcsph_fields.hpp"
#include "sluice/fluid/wcsph/wcsph_pair_term.hpp"
#include "sluice/neighbor/cell_list.hpp"

namespace sluice {

// The rates' SIMD loop runs over whole vectors of 8 floats (AVX2): its candidate ranges are
// widened to a multiple of 8, since the farther particles add nothing and the scalar remainder
// (up to 7 candidates in each of 9 ranges) is slower than one more vector. A GPU thread walks
// its candidates one by one, so there they are not widened.
#if defined(__CUDACC__)
inline constexpr int kRatesRangeMultiple = 1;
#else
inline constexpr int kRatesRangeMultiple = 8;
#endif

// The second half kick of kick-drift-kick: velocity and density from their half-step values
// with the rates, and the pressure of that density. The density goes no lower than the equation
// of state's inverse does (TaitEquation::lowest_density, 0.14 rho0): a particle whose neighbours
// all fly off keeps little more than its own kernel's share of density by continuity (0.12 rho0
// in 3D with the Wendland kernel at h = 1.5 dx), and the density diffusion between such spray
// particles took some below zero; their volumes m / rho, which their neighbours' sums read, then
// grew without bound (F3 at 0.015 m blew up at 0.885 s so).
template <int D>
SLUICE_HOST_DEVICE inline void wcsph_second_half_kick(const WcsphFields<D>& f, std::size_t i,
                                                      Real half_dt, const TaitEquation& eos) {
  for (int a = 0; a < D; ++a) {
    const std::size_t k = D * i + a;
    f.velocity[k] = f.half_velocity[k] + half_dt * f.acceleration[k];
  }
  const Real density = f.half_density[i] + half_dt * f.density_rate[i];
  f.density[i] = density > eos.lowest_density ? density : eos.lowest_density;
  f.pressure[i] = eos.pressure(f.density[i]);
}

// The length of a fluid particle's velocity or acceleration (D reals a particle), zero for the
// rest: the largest of them sets the time step, so host and device take it from one copy.
template <int D>
struct FluidMagnitude {
  WcsphFields<D> f;
  const Real* vector;
  SLUICE_HOST_DEVICE SLUICE_ONE_HOST_COPY double operator()(std::size_t i) const {
    if (!f.fluid(i)) return 0.0;
    double sum = 0;
    for (int a = 0; a < D; ++a) sum += vector[D * i + a] * vector[D * i + a];
    return std::sqrt(sum);
  }
};

// x, v and rho half a kick and a drift on (the first half of kick-drift-kick); velocity and
// density are then predicted to the end of the step (a second half kick with the same rates)
// for the force evaluation. With a transport velocity (transport_velocity.hpp), the drift adds
// half a step of the background pressure's acceleration to the half-step velocity.
template <int D>
struct WcsphKickDrift {
  WcsphFields<D> f;
  Real dt;
  TaitEquation eos;
  const Real* background_acceleration = nullptr;  // with a transport velocity
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    if (!f.fluid(i)) return;
    const Real half_dt = 0.5 * dt;
    for (int a = 0; a < D; ++a) {
      const std::size_t k = D * i + a;
      f.half_velocity[k] = f.velocity[k] + half_dt * f.acceleration[k];
      const Real transport =
          background_acceleration ? half_dt * background_acceleration[k] : Real(0);
      f.position[k] += dt * (f.half_velocity[k] + transport);
    }
    f.half_density[i] = f.density[i] + half_dt * f.density_rate[i];
    wcsph_second_half_kick(f, i, half_dt, eos);
  }
};

// The second half kick, from the half-step values with the new rates.
template <int D>
struct WcsphKick {
  WcsphFields<D> f;
  Real dt;
  TaitEquation eos;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    if (f.fluid(i)) wcsph_second_half_kick(f, i, 0.5 * dt, eos);
  }
};

// Copies particle i into the single-precision arrays the pair loops read (2D: y = 0), and a
// fluid particle into the fluid's own arrays too (fluid_before must hold the counts).
template <int D>
struct WcsphPack {
  WcsphFields<D> f;
  PackedParticles::Arrays packed;
  bool no_slip;
  bool with_rates;  // also p / rho^2 and m / rho, which only the rates read
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    const bool fluid = f.fluid(i);
    for (int a3 = 0; a3 < 3; ++a3) {
      const int a = D == 3 ? a3 : (a3 == 0 ? 0 : 1);
      const bool absent = D == 2 && a3 == 1;
      const std::size_t k = D * i + a;
      packed.position[a3][i] = absent ? 0.0f : static_cast<float>(f.position[k]);
      packed.velocity[a3][i] = absent ? 0.0f : static_cast<float>(f.velocity[k]);
      packed.viscous_velocity[a3][i] =
          absent ? 0.0f : static_cast<float>(fluid ? f.velocity[k] : f.wall_velocity[k]);
    }
    packed.density[i] = static_cast<float>(f.density[i]);
    packed.pressure[i] = static_cast<float>(f.pressure[i]);
    packed.fluid[i] = fluid ? 1.0f : 0.0f;
    if (fluid) {
      const std::uint32_t k = packed.fluid_before[i];
      for (int a3 = 0; a3 < 3; ++a3) {
        packed.fluid_position[a3][k] = packed.position[a3][i];
        packed.fluid_velocity[a3][k] = packed.velocity[a3][i];
      }
      packed.fluid_density[k] = packed.density[i];
      packed.fluid_pressure[k] = packed.pressure[i];
    }
    packed.viscous_weight[i] = (fluid || no_slip) ? 1.0f : 0.0f;
    if (with_rates) {
      const Real inverse_rho = 1 / f.density[i];
      packed.pressure_term[i] = static_cast<float>(f.pressure[i] * inverse_rho * inverse_rho);
      packed.volume[i] = static_cast<float>(f.mass[i] * inverse_rho);
    }
  }
};

// Continuity and momentum of fluid particle i, gathered over its candidates: each range in
// single precision (as SIMD on the host), the ranges added in double.
template <int D, class Kernel>
struct WcsphRates {
  WcsphNeighbourhood<D, Kernel> n;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    const auto& [f, packed, cells, c] = n;
    if (!f.fluid(i)) return;
    const float laminar_i = static_cast<float>(c.two_nu_rho0 / f.density[i]);
    const WcsphOwnParticle<float> own = own_particle(packed, i, laminar_i);
    double acc[3] = {0, 0, 0}, density = 0;
    cells.template for_each_clipped_range<kRatesRangeMultiple>(
        f.position + D * i, [&](std::uint32_t begin, std::uint32_t end) {
          // A local copy of the view, as this loop has always read it: the compiler then splits the
          // SIMD sums the same way, and the results stay the same to the bit.
          const PackedParticles::View p = packed;
          float ax = 0, ay = 0, az = 0, drho = 0;
#if !defined(__CUDACC__)
#pragma omp simd reduction(+ : ax, ay, az, drho)
#endif
          for (std::size_t j = begin; j < end; ++j)
            add_wcsph_pair_term(p, own, j, c.pair, c.kernel, ax, ay, az, drho);
          acc[0] += ax;
          acc[1] += ay;
          acc[2] += az;
          density += drho;
        });
    for (int a = 0; a < D; ++a) {
      const int a3 = D == 3 ? a : 2 * a;
      f.acceleration[D * i + a] = acc[a3] + c.gravity[a3];
    }
    f.density_rate[i] = density;
  }
};

// The fluid's force on body particle w (force[3 k ..] for its body point k): minus the force
// that w exerts on its fluid neighbours i, from the very pair term of the rates, in double.
template <int D, class Kernel>
struct WcsphBodyPointForce {
  WcsphNeighbourhood<D, Kernel> n;
  Real* force;
  SLUICE_HOST_DEVICE void operator()(std::size_t w) const {
    const auto& [f, packed, cells, c] = n;
    const std::int32_t k = f.body_point[w];
    if (k < 0) return;
    double sum[3] = {0, 0, 0};
    // Beyond the kernel's support (2h, with a margin for the float kernel's rounding) a fluid
    // particle's term is exactly zero: skipped, it leaves the sum as it was.
    const double support2 = 4 * c.kernel.h * c.kernel.h * (1 + 1e-5);
    const double xw = packed.x[w], yw = packed.y[w], zw = packed.z[w];
    cells.for_each_clipped_range(f.position + D * w, [&](std::uint32_t begin, std::uint32_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        if (packed.fluid[i] == 0) continue;
        const double rx = packed.x[i] - xw, ry = packed.y[i] - yw, rz = packed.z[i] - zw;
        if (rx * rx + ry * ry + rz * rz > support2) continue;
        const auto own = own_particle(packed, i, c.two_nu_rho0 / f.density[i]);
        double ax = 0, ay = 0, az = 0, drho = 0;
        add_wcsph_pair_term(packed, own, w, c.pair, c.kernel, ax, ay, az, drho);
        sum[0] -= f.mass[i] * ax;  // minus m_i a_i(w)
        sum[1] -= f.mass[i] * ay;
        sum[2] -= f.mass[i] * az;
      }
    });
    for (int a = 0; a < 3; ++a) force[3 * k + a] = sum[a];
  }
};

}  // namespace sluice
