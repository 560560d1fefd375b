// hypre's conjugate gradient preconditioned by one V-cycle of BoomerAMG (algebraic multigrid),
// on one process: its iteration count barely grows with the problem size.
#pragma once

#include "sluice/linear/sparse_solver.hpp"

namespace sluice {

std::unique_ptr<SparseSolver> make_boomeramg(const SolverSettings& settings);

}  // namespace sluice
