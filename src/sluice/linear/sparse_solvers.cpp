#include "sluice/linear/eigen_cg_solvers.hpp"
#include "sluice/linear/sparse_solver.hpp"
#ifdef SLUICE_WITH_HYPRE
#include "sluice/linear/hypre_solvers.hpp"
#endif

namespace sluice {

std::vector<std::string> sparse_solver_names() {
  std::vector<std::string> names{"cg_diagonal", "cg_incomplete_cholesky", "bicgstab_diagonal"};
#ifdef SLUICE_WITH_HYPRE
  names.push_back("boomeramg");
#endif
  return names;
}

std::unique_ptr<SparseSolver> make_sparse_solver(const std::string& name,
                                                 const SolverSettings& settings) {
  if (name == "cg_diagonal") return make_eigen_cg(CgPreconditioner::kDiagonal, settings);
  if (name == "bicgstab_diagonal") return make_eigen_bicgstab(settings);
  if (name == "cg_incomplete_cholesky") {
    return make_eigen_cg(CgPreconditioner::kIncompleteCholesky, settings);
  }
#ifdef SLUICE_WITH_HYPRE
  if (name == "boomeramg") return make_boomeramg(settings);
#endif
  return nullptr;
}

std::vector<std::string> split_solver_names() {
#ifdef SLUICE_WITH_HYPRE
  return {"cg_diagonal", "bicgstab_diagonal", "boomeramg"};
#else
  return {};
#endif
}

std::unique_ptr<SplitSolver> make_split_solver([[maybe_unused]] const std::string& name,
                                               [[maybe_unused]] const SolverSettings& settings) {
#ifdef SLUICE_WITH_HYPRE
  return make_hypre_split_solver(name, settings);
#else
  return nullptr;
#endif
}

}  // namespace sluice
