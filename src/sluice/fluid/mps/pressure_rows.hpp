// The rows of MPS's pressure equation (pressure_equation.hpp says what they are) as loop bodies
// over plain arrays, one row each: its entries counted, then its values and right-hand side
// written. The host's PressureEquation and a device run (mps_device_run_impl.hpp) assemble
// with the same two.
#pragma once

#include <cstddef>
#include <cstdint>

#include "sluice/core/host_device.hpp"
#include "sluice/fluid/mps/mps_loop_bodies.hpp"
#include "sluice/fluid/mps/mps_operators.hpp"

namespace sluice {

// One entry per particle in each array.
template <int D>
struct PressureEquationInputs {
  MpsOperators<D> op;
  std::size_t particles = 0;
  const Vec<D>* velocity = nullptr;       // u* (walls and bodies: their own)
  const Real* number_density = nullptr;   // n*
  const std::int32_t* surface = nullptr;  // 1 on the free surface
  const std::uint8_t* active = nullptr;   // 1: fluid, or a boundary particle it reaches
  const Real* pressure = nullptr;         // p^n, the last step's
  Real dt = 0;
  Real density = 0;
  Real relaxation = 0;          // gamma
  Real compressibility = 0;     // alpha, 1/Pa
  bool pressure_memory = true;  // m: the divergence part's compressibility as a rate
  // 1 for the wall and body particles whose pressure is extrapolated from the fluid around
  // them; nullptr: every active boundary particle has a Poisson row of its own.
  const std::uint8_t* extrapolated = nullptr;
  // With `extrapolated`: g - a_w of each wall and body particle (`velocity` already holds its
  // u_w + dt (g - a_w)).
  const Vec<D>* wall_gravity = nullptr;

  // Whether particle j's pressure is extrapolated from the fluid rather than solved for.
  SLUICE_HOST_DEVICE bool wall(std::size_t j) const {
    return extrapolated != nullptr && extrapolated[j] != 0;
  }
  // Whether particle i's pressure is an unknown of the equation: active, and not on the free
  // surface (p = 0 there) unless it is a wall extrapolated from the fluid.
  SLUICE_HOST_DEVICE bool unknown(std::size_t i) const {
    return active[i] && (wall(i) || !surface[i]);
  }
  // The coefficient of p_j in particle i's row, zero for a particle outside the row: a wall
  // row, sum_f w_wf (p_w - p_f) = sum_f w_wf rho (g - a_w) . (x_w - x_f) over its fluid
  // neighbours f; a fluid row, the Laplacian over every active neighbour.
  SLUICE_HOST_DEVICE Real coefficient(std::size_t i, std::size_t j) const {
    if (!active[j]) return 0;
    if (wall(i)) return wall(j) ? 0 : op.weight(i, j);
    return op.laplacian_coefficient(i, j);
  }
};

// The entries of row r (particle i): the diagonal and the unknown neighbours in reach
// (row_of[j] >= 0), into count[r + 1].
template <int D>
struct PressureRowCount {
  PressureEquationInputs<D> in;
  const int* row_of;
  const std::size_t* particle_of;
  int* count;
  SLUICE_HOST_DEVICE void operator()(std::size_t r) const {
    const std::size_t i = particle_of[r];
    int entries = 0;
    in.op.neighbours().for_each(i, [&](std::size_t j) {
      if (row_of[j] >= 0 && in.coefficient(i, j) > 0) ++entries;
    });
    count[r + 1] = entries + 1;
  }
};

// Row r's values, from start[r] on, and its right-hand side. Its columns are the unknowns' row
// numbers (row_of[i] is r, or on several ranks the whole system's number of it), the diagonal
// placed in their order: in increasing order where the unknowns are numbered in particle order.
template <int D>
struct PressureRowValues {
  PressureEquationInputs<D> in;
  const int* row_of;
  const std::size_t* particle_of;
  const int* start;
  int* column;
  double* value;
  double* rhs;
  Real density_source, divergence_source, compressibility, memory;
  SLUICE_HOST_DEVICE void operator()(std::size_t r) const {
    const std::size_t i = particle_of[r];
    const MpsOperators<D>& op = in.op;
    int k = start[r];
    int diagonal = -1;
    Real sum = 0, source = 0;
    const bool wall = in.wall(i);
    op.neighbours().for_each(i, [&](std::size_t j) {
      const Real c = in.coefficient(i, j);
      if (c <= 0) return;
      if (wall) source += c * in.density * in.wall_gravity[i].dot(op.position(i) - op.position(j));
      sum += c;
      if (row_of[j] < 0) return;  // p_j = 0 on the surface: only the diagonal sees it
      if (diagonal < 0 && row_of[j] > row_of[i]) diagonal = k++;
      column[k] = row_of[j];
      value[k++] = -c;
    });
    if (diagonal < 0) diagonal = k++;
    column[diagonal] = row_of[i];
    if (wall) {
      value[diagonal] = sum;
      rhs[r] = source;
      return;
    }
    const Real n0 = op.lattice().n0;
    value[diagonal] = sum + compressibility;
    rhs[r] = density_source * (in.number_density[i] - n0) / n0 -
             divergence_source * op.divergence(i, in.velocity, MpsEveryNeighbour{}) +
             memory * in.pressure[i];
  }
};

struct PressureEquationReport {
  std::size_t unknowns = 0;
  std::size_t entries = 0;
  int iterations = 0;
  double relative_residual = 0;
  bool converged = true;
};

}  // namespace sluice
