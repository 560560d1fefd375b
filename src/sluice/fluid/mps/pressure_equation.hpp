// The pressure Poisson equation of incompressible MPS, on the particles that are neither on the
// free surface (p = 0 there) nor out of the fluid's reach:
//   <lap p>_i - alpha rho / dt^2 p_i = -gamma rho / dt^2 (n*_i - n0) / n0
//                                      + (1 - gamma) rho / dt <div u*>_i
//                                      - m (1 - gamma) alpha rho / dt^2 p^n_i
// (source relaxation gamma after Tanaka & Masunaga 2010; artificial compressibility alpha,
// Ikeda et al. 2001). The number-density part asks for n = n0 (1 + alpha p), an equation of
// state; the divergence part asks for a rate, div u = -alpha dp/dt, which needs the last
// pressure p^n (memory m = 1, the default). Without it (m = 0, Ikeda's form) every step
// forgets the pressure the fluid already holds and the water settles compressed: a still tank
// 1 m deep sinks 7.5 % at alpha = 2.55e-7 1/Pa (docs/validation.md, F2).
// Written as A p = b with A = -lap + alpha rho / dt^2.
// Walls and bodies, two ways:
// - extrapolated (the default): every wall and body particle the fluid reaches, dummies
//   included, takes the pressure of its fluid neighbours f carried to it along the hydrostatic
//   gradient of its own acceleration a_w (Adami, Hu & Adams 2012 extrapolate alike in SPH):
//     sum_f w_wf (p_w - p_f) = sum_f w_wf rho (g - a_w) . (x_w - x_f)
//   In the fluid's divergence the wall takes its velocity plus dt (g - a_w), the part of u* the
//   extrapolation has answered for: still water sees no divergence at a wall, and a wall that
//   moves into the water still pushes it through the divergence. A fluid row then sees a full
//   neighbourhood, and still water keeps its hydrostatic pressure under a lid or a held body.
//   A is not symmetric: BiCGSTAB solves it.
// - solved: the first wall layer has Poisson rows of its own, its divergence taken against the
//   wall's velocity, and the dummies behind it fill the number density only (Koshizuka & Oka
//   1996). A is symmetric positive definite. Those rows' source is about half what their
//   one-sided Laplacian needs at rest, which the water under a lid cannot make up
//   (docs/validation.md, B5).
// Each row is assembled by one thread straight into the compressed sparse rows; the solve
// starts from the last pressure.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include "sluice/exec/policy.hpp"
#include "sluice/fluid/mps/mps_loop_bodies.hpp"
#include "sluice/fluid/mps/mps_operators.hpp"
#include "sluice/linear/sparse_solver.hpp"

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

// Row r's values, from start[r] on, its columns in increasing order, and its right-hand side.
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
      if (diagonal < 0 && j > i) diagonal = k++;
      column[k] = row_of[j];
      value[k++] = -c;
    });
    if (diagonal < 0) diagonal = k++;
    column[diagonal] = static_cast<int>(r);
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

template <int D>
class PressureEquation {
 public:
  PressureEquation(const std::string& solver, const SolverSettings& settings)
      : solver_(make_sparse_solver(solver, settings)) {
    if (!solver_) throw std::invalid_argument("unknown sparse solver " + solver);
  }

  void assemble(const PressureEquationInputs<D>& in) {
    const std::size_t n = in.particles;
    // Unknowns numbered in particle order, so each row's columns come out sorted.
    row_of_.assign(n, -1);
    int unknowns = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (in.active[i] && (in.wall(i) || !in.surface[i])) row_of_[i] = unknowns++;
    }
    particle_of_.resize(static_cast<std::size_t>(unknowns));
    for (std::size_t i = 0; i < n; ++i) {
      if (row_of_[i] >= 0) particle_of_[static_cast<std::size_t>(row_of_[i])] = i;
    }
    // Pass 1: entries per row (the diagonal and the unknown neighbours in reach).
    matrix_.resize(unknowns, unknowns);
    int* start = matrix_.outerIndexPtr();
    start[0] = 0;
    exec::Default::for_each_balanced(
        particle_of_.size(), PressureRowCount<D>{in, row_of_.data(), particle_of_.data(), start});
    for (int r = 0; r < unknowns; ++r) start[r + 1] += start[r];
    matrix_.resizeNonZeros(start[unknowns]);
    rhs_.resize(unknowns);
    // Pass 2: the values, and the right-hand side.
    const Real inverse_dt = 1 / in.dt;
    const Real compressibility = in.compressibility * in.density * inverse_dt * inverse_dt;
    PressureRowValues<D> values{in,
                                row_of_.data(),
                                particle_of_.data(),
                                start,
                                matrix_.innerIndexPtr(),
                                matrix_.valuePtr(),
                                rhs_.data(),
                                in.relaxation * in.density * inverse_dt * inverse_dt,
                                (1 - in.relaxation) * in.density * inverse_dt,
                                compressibility,
                                in.pressure_memory ? (1 - in.relaxation) * compressibility : 0};
    exec::Default::for_each_balanced(particle_of_.size(), values);
    report_ = PressureEquationReport{};
    report_.unknowns = particle_of_.size();
    report_.entries = static_cast<std::size_t>(start[unknowns]);
  }

  // Solves from the present `pressure` as the first guess and writes the result back, zero
  // off the unknowns. False when the solver did not reach its tolerance.
  bool solve(std::vector<Real>& pressure) { return solve(pressure.data(), pressure.size()); }
  bool solve(Real* pressure, std::size_t n) {
    guess_.resize(static_cast<Eigen::Index>(particle_of_.size()));
    for (std::size_t r = 0; r < particle_of_.size(); ++r)
      guess_[static_cast<Eigen::Index>(r)] = pressure[particle_of_[r]];
    SolveReport solved;
    solved.converged = true;
    if (!particle_of_.empty()) solved = solver_->solve(matrix_, rhs_, guess_);
    report_.iterations = solved.iterations;
    report_.relative_residual = solved.relative_residual;
    report_.converged = solved.converged;
    exec::Default::for_each(
        n, [&](std::size_t i) { pressure[i] = row_of_[i] >= 0 ? guess_[row_of_[i]] : 0; });
    return solved.converged;
  }

  const PressureEquationReport& report() const { return report_; }
  const SparseRows& matrix() const { return matrix_; }
  const Eigen::VectorXd& rhs() const { return rhs_; }

 private:
  std::unique_ptr<SparseSolver> solver_;
  SparseRows matrix_;
  Eigen::VectorXd rhs_, guess_;
  std::vector<int> row_of_;
  std::vector<std::size_t> particle_of_;
  PressureEquationReport report_;
};

}  // namespace sluice
