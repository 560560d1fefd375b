// The loop bodies of an MPS step (mps_model.hpp), each a function of one particle's index over
// plain arrays, so that the OpenMP policy runs them on the host's particle set and a device
// backend on its copy of it: the prediction, the collisions, the number density and the free
// surface, the extrapolated walls' inputs, the equation of state, and the pressure's correction.
// The operators are mps_operators.hpp's.
#pragma once

#include <cmath>
#include <cstdint>

#include "sluice/core/host_device.hpp"
#include "sluice/fluid/mps/mps_operators.hpp"
#include "sluice/neighbor/cell_list.hpp"

namespace sluice {

// What an MPS particle is: fluid, boundary (wall or body particle in the pressure equation) or
// dummy (behind the boundary, in the number density only).
enum MpsRole : std::int32_t { kMpsFluid = 0, kMpsBoundary = 1, kMpsDummy = 2 };

// The arrays an MPS step reads and writes, one entry (a vector: D reals) per particle.
template <int D>
struct MpsArrays {
  Vec<D>* position = nullptr;
  Vec<D>* velocity = nullptr;
  Real* pressure = nullptr;
  const std::int32_t* kind = nullptr;  // ParticleKind's integer: 0 is fluid
  const std::int32_t* body_point = nullptr;
  const std::int32_t* role = nullptr;  // MpsRole
  Real* number_density = nullptr;
  std::int32_t* surface = nullptr;  // 1 on the free surface
  // 1: fluid, or a wall or body particle the fluid reaches (in the pressure's operators).
  std::uint8_t* active = nullptr;
  Vec<D>* scratch = nullptr;  // a velocity or its change, between two loops of a stage
  SLUICE_HOST_DEVICE bool fluid(std::size_t i) const { return kind[i] == 0; }
};

// Which neighbours an operator sums over.
struct MpsNotDummy {
  const std::int32_t* role;
  SLUICE_HOST_DEVICE bool operator()(std::size_t j) const { return role[j] != kMpsDummy; }
};
struct MpsFluidOnly {
  const std::int32_t* role;
  SLUICE_HOST_DEVICE bool operator()(std::size_t j) const { return role[j] == kMpsFluid; }
};
struct MpsActive {
  const std::uint8_t* active;
  SLUICE_HOST_DEVICE bool operator()(std::size_t j) const { return active[j] != 0; }
};
struct MpsEveryNeighbour {
  SLUICE_HOST_DEVICE bool operator()(std::size_t) const { return true; }
};

// Whether particle i has a row in the neighbour list: fluid; boundary particles (dummies too
// with extrapolated walls) with fluid in the cells around them, which a count of the fluid
// before each particle of the cell-sorted set answers per cell range (dry walls cost nothing).
template <int D>
struct MpsListed {
  const std::int32_t* role;
  const Real* position;  // D reals a particle
  CellGridView<D> cells;
  const std::uint32_t* fluid_before;
  bool dummies;
  SLUICE_HOST_DEVICE bool operator()(std::size_t i) const {
    if (role[i] == kMpsFluid) return true;
    if (role[i] == kMpsDummy && !dummies) return false;
    bool wet = false;
    cells.for_each_candidate_range(position + D * i, [&](std::uint32_t begin, std::uint32_t end) {
      wet = wet || fluid_before[end] > fluid_before[begin];
    });
    return wet;
  }
};

// u* = u + dt (g + nu lap u) into the scratch (the walls' and bodies' own velocities, no-slip,
// enter the Laplacian; the dummies do not).
template <int D>
struct MpsPrediction {
  MpsArrays<D> a;
  MpsOperators<D> op;
  Vec<D> gravity;
  Real nu, dt;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    a.scratch[i] = a.velocity[i];
    if (!a.fluid(i)) return;
    Vec<D> acceleration = gravity;
    if (nu > 0) acceleration += nu * op.laplacian(i, a.velocity, MpsNotDummy{a.role});
    a.scratch[i] += dt * acceleration;
  }
};

// A fluid particle takes the scratch's velocity and moves with it: x += dt u.
template <int D>
struct MpsTakeVelocity {
  MpsArrays<D> a;
  Real dt;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    if (!a.fluid(i)) return;
    a.velocity[i] = a.scratch[i];
    a.position[i] += dt * a.velocity[i];
  }
};

// A fluid particle's velocity changes by the scratch, and it moves by dt times that change.
template <int D>
struct MpsAddVelocity {
  MpsArrays<D> a;
  Real dt;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    if (!a.fluid(i)) return;
    a.velocity[i] += a.scratch[i];
    a.position[i] += dt * a.scratch[i];
  }
};

// Fluid particles closer than `reach` that approach each other exchange the approaching part of
// their relative velocity with restitution e (Koshizuka et al. 1998; Lee et al. 2011): a guard
// against the clustering that MPS's pressure cannot resolve. Walls and bodies count as
// infinitely heavy. Each particle gathers its own change into the scratch.
template <int D>
struct MpsCollision {
  MpsArrays<D> a;
  NeighbourView neighbours;
  Real reach2, restitution;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    a.scratch[i] = Vec<D>::Zero();
    if (!a.fluid(i)) return;
    Vec<D> change = Vec<D>::Zero();
    neighbours.for_each(i, [&](std::size_t j) {
      if (a.role[j] == kMpsDummy) return;
      const Vec<D> r = a.position[j] - a.position[i];
      const Real r2 = r.squaredNorm();
      if (r2 >= reach2 || r2 <= 0) return;
      const Vec<D> normal = r / std::sqrt(r2);
      const Real approach = (a.velocity[i] - a.velocity[j]).dot(normal);
      if (approach <= 0) return;
      const Real share = a.fluid(j) ? 0.5 : 1.0;  // equal masses, or a wall
      change -= share * (1 + restitution) * approach * normal;
    });
    a.scratch[i] = change;
  }
};

// Number density n*, and the free surface: n* < dense, confirmed by fewer neighbours than
// `crowded` (Tanaka & Masunaga 2010), so that an inner particle whose density dips is not taken
// for a surface one. Wall particles that no fluid particle reaches are inactive. `dummies`:
// whether dummy particles have a number density and may be active (extrapolated walls).
template <int D>
struct MpsNumberDensity {
  MpsArrays<D> a;
  MpsOperators<D> op;
  Real dense, crowded;
  bool dummies;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    a.surface[i] = 0;
    a.number_density[i] = 0;
    a.active[i] = 0;
    if (a.role[i] == kMpsDummy && !dummies) return;
    int count = 0;
    a.number_density[i] = op.number_density(i, MpsEveryNeighbour{}, count);
    a.surface[i] = (a.number_density[i] < dense && count < crowded) ? 1 : 0;
    bool reached = a.role[i] == kMpsFluid;
    if (!reached) {
      op.number_density(i, MpsFluidOnly{a.role}, count);
      reached = count > 0;
    }
    a.active[i] = reached ? 1 : 0;
  }
};

// With extrapolated walls, each wall and body particle: whether the fluid reaches it, g - a_w
// (a_w its body point's acceleration, 3 reals a point), and its velocity carried on by
// dt (g - a_w) for the fluid's divergence (pressure_equation.hpp); a fluid particle its own.
template <int D>
struct MpsWallInputs {
  MpsArrays<D> a;
  const Real* point_acceleration;
  Vec<D> gravity;
  Real dt;
  std::uint8_t* extrapolated;
  Vec<D>* wall_gravity;
  Vec<D>* source_velocity;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    source_velocity[i] = a.velocity[i];
    extrapolated[i] = 0;
    wall_gravity[i] = Vec<D>::Zero();
    if (a.fluid(i)) return;
    extrapolated[i] = a.active[i];
    const std::int32_t k = a.body_point[i];
    Vec<D> g = gravity;
    if (k >= 0) {
      const Real* acceleration = point_acceleration + 3 * k;
      for (int axis = 0; axis < D; ++axis) g[axis] -= acceleration[D == 3 ? axis : 2 * axis];
    }
    wall_gravity[i] = g;
    source_velocity[i] += dt * g;
  }
};

// The explicit variant: p = c0^2 rho0 (n* - n0) / n0 (Shakibaeinia & Jin 2010), zero on the
// surface and on inactive boundary particles.
template <int D>
struct MpsStateEquation {
  MpsArrays<D> a;
  Real stiffness, n0;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    const bool free = a.active[i] == 0 || a.surface[i] != 0;
    a.pressure[i] = free ? 0 : stiffness * (a.number_density[i] - n0);
  }
};

// The pressure not below zero (a NaN stays one, for the divergence guard to find).
template <int D>
struct MpsClampPressure {
  MpsArrays<D> a;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    if (a.pressure[i] < 0) a.pressure[i] = 0;
  }
};

// -dt / rho grad p into the scratch, over the active neighbours; the gradient against p_i
// rather than the neighbourhood's smallest where n* < `full` (a one-sided neighbourhood), and
// in the plain d / n0 form on the free surface.
template <int D>
struct MpsPressureCorrection {
  MpsArrays<D> a;
  MpsOperators<D> op;
  Real scale, full;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    if (!a.fluid(i)) return;
    a.scratch[i] = -scale * op.gradient(i, a.pressure, MpsActive{a.active}, a.surface[i] != 0,
                                        !(a.number_density[i] < full));
  }
};

}  // namespace sluice
