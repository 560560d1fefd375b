// Iterative solvers for the sparse systems of the implicit models (the MPS pressure equation),
// behind one interface so that a model names its solver in the case file: for symmetric
// positive definite ones, Eigen's conjugate gradient with a diagonal or incomplete-Cholesky
// preconditioner, and hypre's BoomerAMG as the preconditioner of hypre's conjugate gradient
// when sluice is built with hypre (docs/performance.md compares them); for those that are not
// symmetric, Eigen's BiCGSTAB with a diagonal preconditioner.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string>
#include <vector>

namespace sluice {

// Rows stored contiguously: each row is assembled by one thread, and Eigen multiplies a
// row-major matrix by a vector on all threads.
using SparseRows = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

class HypreSession;  // hypre_session.hpp

struct SolverSettings {
  double tolerance = 1e-8;  // on the residual relative to the right-hand side, |r| / |b|
  int max_iterations = 1000;
  // The process's MPI and hypre, which a hypre solver starts at its first solve; it has none
  // without one (made without it, it throws std::logic_error when asked to solve).
  HypreSession* hypre = nullptr;
};

struct SolveReport {
  int iterations = 0;
  double relative_residual = 0;
  bool converged = false;
};

class SparseSolver {
 public:
  virtual ~SparseSolver() = default;
  // Solves a x = b (for the conjugate gradients, `a` symmetric positive definite), starting
  // from the x given (a warm start from the last solution saves iterations when the systems
  // change slowly).
  virtual SolveReport solve(const SparseRows& a, const Eigen::VectorXd& b, Eigen::VectorXd& x) = 0;
};

// A system split by rows over the run's ranks (mpirun), each rank holding its own rows.
class SplitSolver {
 public:
  virtual ~SplitSolver() = default;
  // Collective: every rank calls it with its rows. `a` holds rows first_row, first_row + 1, ...
  // of the whole system (as many as `b`), its columns numbered as the whole system's rows; x
  // (the first guess, then the solution) and b are this rank's entries of them. The report is
  // of the whole system.
  virtual SolveReport solve(const SparseRows& a, int first_row, const Eigen::VectorXd& b,
                            Eigen::VectorXd& x) = 0;
};

// The solvers this build offers, by name: "cg_diagonal", "cg_incomplete_cholesky" and, built
// with hypre, "boomeramg".
std::vector<std::string> sparse_solver_names();
// nullptr for a name not in sparse_solver_names().
std::unique_ptr<SparseSolver> make_sparse_solver(const std::string& name,
                                                 const SolverSettings& settings);
// Those of them that solve a system split over ranks (hypre's, in a build with it): the same
// method under the same name, in another library.
std::vector<std::string> split_solver_names();
// nullptr for a name not in split_solver_names().
std::unique_ptr<SplitSolver> make_split_solver(const std::string& name,
                                               const SolverSettings& settings);

}  // namespace sluice
