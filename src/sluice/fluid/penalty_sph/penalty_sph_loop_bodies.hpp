// The fluid's loop bodies of a penalty-sph step (penalty_sph_model.hpp), each a function of one
// particle's index over plain arrays, so that the OpenMP policy runs them on the host's particle
// set and a device backend on its copy of it: the half kicks, the density by summation and its
// pressure, the fluid's own force, and the pressure force the fluid puts on each body particle.
// (The drift through the solids is solid_contact_stepper.hpp's.)
#pragma once

#include <cmath>
#include <cstdint>

#include "sluice/core/host_device.hpp"
#include "sluice/kernels/muller_kernels.hpp"
#include "sluice/neighbor/cell_list.hpp"

namespace sluice {

// The arrays a penalty-sph step reads and writes, one entry (a vector: D reals) per particle.
template <int D>
struct PenaltySphArrays {
  Vec<D>* position = nullptr;
  Vec<D>* velocity = nullptr;
  Real* density = nullptr;
  Real* pressure = nullptr;
  const Real* mass = nullptr;
  const std::int32_t* kind = nullptr;  // ParticleKind's integer: 0 is fluid
  const std::int32_t* body_point = nullptr;
  const Real* solid_spacing = nullptr;  // L_b of a solid particle
  Vec<D>* acceleration = nullptr;
  Vec<D>* half_velocity = nullptr;
  const Real* point_acceleration = nullptr;  // 3 reals a body point
  SLUICE_HOST_DEVICE bool fluid(std::size_t i) const { return kind[i] == 0; }
};

// The model's constants, as penalty_sph_model.hpp derives them from its parameters.
template <int D>
struct PenaltySphConstants {
  MullerKernels<D> kernels;
  Vec<D> gravity;
  Real rest_density, gas_stiffness;
  bool keep_negative_pressure;
  Real lattice_correction;  // rho0 over a full lattice's poly6 sum
  Real pressure_weight;     // w of -sum V_j w (p_i + p_j) grad W
  Real gradient_gain;       // G of lattice_sums.hpp
  Real damping;             // alpha c0 h of the artificial viscosity [m^2/s]
  Real viscosity;           // mu [Pa s]
  Real buoyancy, surface_tension, surface_threshold;
};

// fn(j, r_ij, r^2) for every particle j != i within the kernel's support h of particle i
// (r_ij = x_i - x_j), in the cells' order: CellList::for_each_neighbor over plain arrays.
template <int D, class Fn>
SLUICE_HOST_DEVICE void for_each_penalty_neighbour(const CellGridView<D>& cells, const Vec<D>* x,
                                                   std::size_t i, Real radius2, Fn&& fn) {
  cells.for_each_candidate_range(x[i].data(), [&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t j = begin; j < end; ++j) {
      const Vec<D> rij = x[i] - x[j];
      const Real r2 = rij.squaredNorm();
      if (r2 < radius2 && j != i) fn(static_cast<std::size_t>(j), rij, r2);
    }
  });
}

// The pressure solid particle b holds for fluid particle i, x_i - x_b = rib away: p_i continued
// to it along the gradient that holds the water still against b, rho_i (g - a_b) / (w G)
// (Adami, Hu & Adams 2012; a_b, a body point's acceleration, is zero for walls and layers). A
// zero gradient there (p_b = p_i) would press a face with the pressure half a spacing inside
// the water: +12 % on the lift of B5's parked wheels.
template <int D>
SLUICE_HOST_DEVICE inline Real penalty_solid_pressure(const PenaltySphArrays<D>& a,
                                                      const PenaltySphConstants<D>& c,
                                                      std::size_t b, Real p_i, Real rho_i,
                                                      const Vec<D>& rib) {
  Vec<D> felt = c.gravity;
  const std::int32_t point = a.body_point[b];
  if (point >= 0) {
    const Real* acceleration = a.point_acceleration + 3 * point;
    for (int axis = 0; axis < D; ++axis) felt[axis] -= acceleration[D == 3 ? axis : 2 * axis];
  }
  const Real p = p_i - rho_i / (c.pressure_weight * c.gradient_gain) * felt.dot(rib);
  return !c.keep_negative_pressure && p < 0 ? 0 : p;  // a NaN stays one, for the guard
}

// Half a kick with the held fluid force: v_half = v + dt/2 a.
template <int D>
struct PenaltyHalfKick {
  PenaltySphArrays<D> a;
  Real dt;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    if (a.fluid(i)) a.half_velocity[i] = a.velocity[i] + 0.5 * dt * a.acceleration[i];
  }
};

// The second half kick: v = v_half + dt/2 a.
template <int D>
struct PenaltyKick {
  PenaltySphArrays<D> a;
  Real dt;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    if (a.fluid(i)) a.velocity[i] = a.half_velocity[i] + 0.5 * dt * a.acceleration[i];
  }
};

// rho_i = sum over the fluid (i included) of m_j W_poly6, scaled to rho0 on a full lattice;
// p_i = k (rho_i - rho0), by default not below zero: a particle at the free surface or a wall
// misses part of its neighbours, and the tension of its density deficit would clump the
// surface. A solid particle counts as the fluid it displaces, rho0 L_b^D, so that the density
// next to a wall is whole and its pressure holds the water above.
template <int D>
struct PenaltyDensity {
  PenaltySphArrays<D> a;
  PenaltySphConstants<D> c;
  CellGridView<D> cells;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    if (!a.fluid(i)) return;
    Real rho = a.mass[i] * c.kernels.poly6(0);
    for_each_penalty_neighbour(
        cells, a.position, i, c.kernels.h2, [&](std::size_t j, const Vec<D>&, Real r2) {
          const Real m = a.fluid(j) ? a.mass[j] : c.rest_density * std::pow(a.solid_spacing[j], D);
          rho += m * c.kernels.poly6(std::sqrt(r2));
        });
    a.density[i] = c.lattice_correction * rho;
    rho = a.density[i];
    const Real pressure = c.gas_stiffness * (rho - c.rest_density);
    a.pressure[i] = !c.keep_negative_pressure && pressure < 0 ? 0 : pressure;
  }
};

// The fluid's own force per unit mass, gravity and buoyancy included (the solids act in the
// drift): the symmetric pressure force, with a solid particle holding the fluid's pressure
// continued to it (so the water's weight rests on the pressure at a wall as inside, not on the
// penalty springs of its first row alone); viscosity through the viscosity kernel's Laplacian;
// Monaghan's artificial viscosity on approaching pairs, on the pair's mean density so that i
// and j feel equal and opposite forces; surface tension from the colour field.
template <int D>
struct PenaltyForces {
  PenaltySphArrays<D> a;
  PenaltySphConstants<D> c;
  CellGridView<D> cells;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    if (!a.fluid(i)) return;
    const MullerKernels<D>& k = c.kernels;
    const Real rho_i = a.density[i];
    Vec<D> pressure = Vec<D>::Zero(), viscous = Vec<D>::Zero(), normal = Vec<D>::Zero();
    Real curvature = a.mass[i] / rho_i * k.poly6_laplacian(0);
    for_each_penalty_neighbour(
        cells, a.position, i, k.h2, [&](std::size_t j, const Vec<D>& rij, Real r2) {
          const Real r = std::sqrt(r2);
          if (!a.fluid(j)) {
            const Real p_j = penalty_solid_pressure(a, c, j, a.pressure[i], rho_i, rij);
            pressure -= c.pressure_weight * std::pow(a.solid_spacing[j], D) *
                        (a.pressure[i] + p_j) * k.spiky_gradient_factor(r) * rij;
            return;
          }
          const Real volume = a.mass[j] / a.density[j];
          pressure -= volume * c.pressure_weight * (a.pressure[i] + a.pressure[j]) *
                      k.spiky_gradient_factor(r) * rij;
          viscous += volume * k.viscosity_laplacian(r) * (a.velocity[j] - a.velocity[i]);
          const Real approach = (a.velocity[i] - a.velocity[j]).dot(rij);
          if (approach < 0 && c.damping > 0) {
            const Real mu = approach / (r2 + 0.01 * k.h2);
            const Real mean_density = 0.5 * (rho_i + a.density[j]);
            pressure += a.mass[j] * rho_i / mean_density * c.damping * mu *
                        k.spiky_gradient_factor(r) * rij;
          }
          normal += volume * k.poly6_gradient_factor(r) * rij;
          curvature += volume * k.poly6_laplacian(r);
        });
    Vec<D> f = pressure + c.viscosity * viscous +
               (rho_i + c.buoyancy * (rho_i - c.rest_density)) * c.gravity;
    const Real n = normal.norm();
    if (c.surface_tension > 0 && n > c.surface_threshold) {
      f -= c.surface_tension * curvature * normal / n;
    }
    a.acceleration[i] = f / rho_i;
  }
};

// Minus the pressure force body particle b exerts on its fluid neighbours, which hold their own
// pressure on it (PenaltyForces), into force[its body point].
template <int D>
struct PenaltyBodyPressureForce {
  PenaltySphArrays<D> a;
  PenaltySphConstants<D> c;
  CellGridView<D> cells;
  Vec<D>* force;
  SLUICE_HOST_DEVICE void operator()(std::size_t b) const {
    const std::int32_t k = a.body_point[b];
    if (k < 0) return;
    Vec<D> sum = Vec<D>::Zero();
    for_each_penalty_neighbour(
        cells, a.position, b, c.kernels.h2, [&](std::size_t i, const Vec<D>& rbi, Real r2) {
          if (!a.fluid(i)) return;
          // minus the force on i, -(-V_i w V_b (p_i + p_b) grad W(x_i -
          // x_b)), grad W along -rbi
          const Real p_b =
              penalty_solid_pressure(a, c, b, a.pressure[i], a.density[i], Vec<D>(-rbi));
          sum -= a.mass[i] / a.density[i] * c.pressure_weight * std::pow(a.solid_spacing[b], D) *
                 (a.pressure[i] + p_b) * c.kernels.spiky_gradient_factor(std::sqrt(r2)) * rbi;
        });
    force[k] = sum;
  }
};

}  // namespace sluice
