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
// starts from the last pressure. On several ranks each holds the rows of its own particles.
#pragma once

#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "sluice/exec/policy.hpp"
#include "sluice/fluid/mps/pressure_rows.hpp"
#include "sluice/linear/sparse_solver.hpp"
#include "sluice/parallel/communicator.hpp"

namespace sluice {

template <int D>
class PressureEquation {
 public:
  // With `ranks` split, the system is split over them by rows (a rank's rows are its own
  // particles' unknowns) and solved by the split solver of that name (hypre's).
  PressureEquation(const std::string& solver, const SolverSettings& settings,
                   const Communicator& ranks = Communicator::alone())
      : ranks_(ranks) {
    if (ranks.split()) {
      split_solver_ = make_split_solver(solver, settings);
    } else {
      solver_ = make_sparse_solver(solver, settings);
    }
    if (!solver_ && !split_solver_) throw std::invalid_argument("unknown sparse solver " + solver);
  }

  // One rank alone: numbers every unknown and assembles their rows.
  void assemble(const PressureEquationInputs<D>& in) {
    number_unknowns(in, nullptr);
    assemble_numbered(in);
  }

  // Numbers the unknowns that `kinds` counts (null: every one; a ghost's kind is -1: its owner
  // numbers it), in particle order, the ranks' one after another. A ghost's number is then its
  // owner's to give it: row_numbers() (collective where split).
  void number_unknowns(const PressureEquationInputs<D>& in, const std::int32_t* kinds) {
    const std::size_t n = in.particles;
    row_of_.assign(n, -1);
    particle_of_.clear();
    for (std::size_t i = 0; i < n; ++i) {
      if ((kinds == nullptr || kinds[i] >= 0) && in.unknown(i)) particle_of_.push_back(i);
    }
    const double mine = static_cast<double>(particle_of_.size());
    const std::vector<double> counts = ranks_.gather_all(std::span<const double>(&mine, 1));
    first_row_ = 0;
    global_unknowns_ = 0;
    for (int r = 0; r < ranks_.size(); ++r) {
      if (r < ranks_.rank()) first_row_ += static_cast<int>(counts[std::size_t(r)]);
      global_unknowns_ += static_cast<std::size_t>(counts[std::size_t(r)]);
    }
    for (std::size_t r = 0; r < particle_of_.size(); ++r)
      row_of_[particle_of_[r]] = first_row_ + static_cast<int>(r);
  }
  // Each particle's row number in the whole system, -1 off the unknowns.
  std::vector<int>& row_numbers() { return row_of_; }

  // The rows of the unknowns numbered last (number_unknowns, and the ghosts' numbers).
  void assemble_numbered(const PressureEquationInputs<D>& in) {
    const int unknowns = static_cast<int>(particle_of_.size());
    // Pass 1: entries per row (the diagonal and the unknown neighbours in reach).
    matrix_.resize(unknowns, static_cast<Eigen::Index>(global_unknowns_));
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
    report_.unknowns = global_unknowns_;
    report_.entries = static_cast<std::size_t>(ranks_.sum(double(start[unknowns])));
  }

  // Solves from the present `pressure` as the first guess and writes the result back to the
  // rows' particles, zero elsewhere (a ghost's is its owner's to give). False when the solver
  // did not reach its tolerance.
  bool solve(std::vector<Real>& pressure) { return solve(pressure.data(), pressure.size()); }
  bool solve(Real* pressure, std::size_t n) {
    guess_.resize(static_cast<Eigen::Index>(particle_of_.size()));
    for (std::size_t r = 0; r < particle_of_.size(); ++r)
      guess_[static_cast<Eigen::Index>(r)] = pressure[particle_of_[r]];
    SolveReport solved;
    solved.converged = true;
    if (global_unknowns_ > 0) {
      solved = split_solver_ ? split_solver_->solve(matrix_, first_row_, rhs_, guess_)
                             : solver_->solve(matrix_, rhs_, guess_);
    }
    report_.iterations = solved.iterations;
    report_.relative_residual = solved.relative_residual;
    report_.converged = solved.converged;
    const int rows = static_cast<int>(particle_of_.size());
    exec::Default::for_each(n, [&](std::size_t i) {
      const int r = row_of_[i] - first_row_;
      pressure[i] = row_of_[i] >= 0 && r < rows && r >= 0 ? guess_[r] : 0;
    });
    return solved.converged;
  }

  const PressureEquationReport& report() const { return report_; }
  const SparseRows& matrix() const { return matrix_; }
  const Eigen::VectorXd& rhs() const { return rhs_; }

 private:
  Communicator ranks_;
  std::unique_ptr<SparseSolver> solver_;
  std::unique_ptr<SplitSolver> split_solver_;
  SparseRows matrix_;
  Eigen::VectorXd rhs_, guess_;
  std::vector<int> row_of_;
  std::vector<std::size_t> particle_of_;
  int first_row_ = 0;
  std::size_t global_unknowns_ = 0;
  PressureEquationReport report_;
};

}  // namespace sluice
