// Eigen's preconditioned conjugate gradient (Eigen/IterativeLinearSolvers).
#pragma once

#include "sluice/linear/sparse_solver.hpp"

namespace sluice {

enum class CgPreconditioner { kDiagonal, kIncompleteCholesky };

std::unique_ptr<SparseSolver> make_eigen_cg(CgPreconditioner preconditioner,
                                            const SolverSettings& settings);

}  // namespace sluice
