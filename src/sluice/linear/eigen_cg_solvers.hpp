// Eigen's preconditioned conjugate gradient and BiCGSTAB (Eigen/IterativeLinearSolvers).
#pragma once

#include "sluice/linear/sparse_solver.hpp"

namespace sluice {

enum class CgPreconditioner { kDiagonal, kIncompleteCholesky };

std::unique_ptr<SparseSolver> make_eigen_cg(CgPreconditioner preconditioner,
                                            const SolverSettings& settings);
// Eigen's stabilised biconjugate gradient with a diagonal preconditioner: for systems that are
// not symmetric.
std::unique_ptr<SparseSolver> make_eigen_bicgstab(const SolverSettings& settings);

}  // namespace sluice
