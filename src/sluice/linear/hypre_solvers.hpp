// hypre's Krylov solvers on its parallel sparse rows (ParCSR): the conjugate gradient
// preconditioned by one V-cycle of BoomerAMG (algebraic multigrid: its iteration count barely
// grows with the problem size), and, for a system split over the run's ranks, the conjugate
// gradient and BiCGSTAB with a diagonal (Jacobi) preconditioner, the methods of Eigen's
// solvers of those names (eigen_cg_solvers.hpp) on one process.
#pragma once

#include "sluice/linear/sparse_solver.hpp"

namespace sluice {

std::unique_ptr<SparseSolver> make_boomeramg(const SolverSettings& settings);

// "boomeramg", "cg_diagonal", "bicgstab_diagonal" as hypre's; nullptr for another name.
std::unique_ptr<SplitSolver> make_hypre_split_solver(const std::string& name,
                                                     const SolverSettings& settings);

}  // namespace sluice
