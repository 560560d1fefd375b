#include "sluice/linear/hypre_solvers.hpp"

#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>
#include <mpi.h>

#include <numeric>
#include <stdexcept>

#include "sluice/linear/hypre_session.hpp"

namespace sluice {

namespace {

enum class Method { kConjugateGradient, kBiCgStab };
constexpr int kBiCgStabAttempts = 5;
enum class Preconditioner { kBoomerAmg, kDiagonal };

// One Krylov method with one preconditioner over the run's ranks (MPI_COMM_WORLD: on one
// process, that process alone), each rank's rows given as it holds them.
class HypreKrylov final : public SplitSolver {
 public:
  HypreKrylov(Method method, Preconditioner preconditioner, const SolverSettings& settings)
      : method_(method), preconditioner_(preconditioner), settings_(settings) {}

  SolveReport solve(const SparseRows& a, int first_row, const Eigen::VectorXd& b,
                    Eigen::VectorXd& x) override {
    if (settings_.hypre == nullptr)
      throw std::logic_error("hypre solver: made without the process's hypre session");
    settings_.hypre->start();
    const HYPRE_Int n = static_cast<HYPRE_Int>(b.size());
    // A rank with no rows holds the empty range [first_row, first_row - 1].
    const HYPRE_BigInt lower = first_row, upper = first_row + n - 1;
    HYPRE_IJMatrix matrix = nullptr;
    HYPRE_IJMatrixCreate(MPI_COMM_WORLD, lower, upper, lower, upper, &matrix);
    HYPRE_IJMatrixSetObjectType(matrix, HYPRE_PARCSR);
    std::vector<HYPRE_Int> row_sizes(static_cast<std::size_t>(n));
    for (HYPRE_Int i = 0; i < n; ++i)
      row_sizes[i] = a.outerIndexPtr()[i + 1] - a.outerIndexPtr()[i];
    HYPRE_IJMatrixSetRowSizes(matrix, row_sizes.data());
    HYPRE_IJMatrixInitialize(matrix);
    std::vector<HYPRE_BigInt> rows(static_cast<std::size_t>(n));
    std::iota(rows.begin(), rows.end(), lower);
    HYPRE_IJMatrixSetValues(matrix, n, row_sizes.data(), rows.data(), a.innerIndexPtr(),
                            a.valuePtr());
    HYPRE_IJMatrixAssemble(matrix);
    HYPRE_ParCSRMatrix parcsr = nullptr;
    HYPRE_IJMatrixGetObject(matrix, reinterpret_cast<void**>(&parcsr));

    HYPRE_IJVector rhs = vector(b, lower, rows);
    HYPRE_IJVector solution = vector(x, lower, rows);
    HYPRE_ParVector par_rhs = nullptr, par_solution = nullptr;
    HYPRE_IJVectorGetObject(rhs, reinterpret_cast<void**>(&par_rhs));
    HYPRE_IJVectorGetObject(solution, reinterpret_cast<void**>(&par_solution));

    HYPRE_Solver amg = nullptr;
    HYPRE_PtrToParSolverFcn precondition = HYPRE_ParCSRDiagScale;
    HYPRE_PtrToParSolverFcn precondition_setup = HYPRE_ParCSRDiagScaleSetup;
    if (preconditioner_ == Preconditioner::kBoomerAmg) {
      HYPRE_BoomerAMGCreate(&amg);
      HYPRE_BoomerAMGSetMaxIter(amg, 1);
      HYPRE_BoomerAMGSetTol(amg, 0.0);
      HYPRE_BoomerAMGSetPrintLevel(amg, 0);
      precondition = HYPRE_BoomerAMGSolve;
      precondition_setup = HYPRE_BoomerAMGSetup;
    }
    HYPRE_Solver krylov = nullptr;
    HYPRE_Int iterations = 0;
    HYPRE_Real residual = 0;
    // Both stop at |r| / |b| in the 2-norm, as Eigen's.
    if (method_ == Method::kConjugateGradient) {
      HYPRE_ParCSRPCGCreate(MPI_COMM_WORLD, &krylov);
      HYPRE_ParCSRPCGSetTol(krylov, settings_.tolerance);
      HYPRE_ParCSRPCGSetMaxIter(krylov, settings_.max_iterations);
      HYPRE_ParCSRPCGSetTwoNorm(krylov, 1);
      HYPRE_ParCSRPCGSetPrecond(krylov, precondition, precondition_setup, amg);
      HYPRE_ParCSRPCGSetup(krylov, parcsr, par_rhs, par_solution);
      HYPRE_ParCSRPCGSolve(krylov, parcsr, par_rhs, par_solution);
      HYPRE_ParCSRPCGGetNumIterations(krylov, &iterations);
      HYPRE_ParCSRPCGGetFinalRelativeResidualNorm(krylov, &residual);
      HYPRE_ParCSRPCGDestroy(krylov);
    } else {
      HYPRE_ParCSRBiCGSTABCreate(MPI_COMM_WORLD, &krylov);
      HYPRE_ParCSRBiCGSTABSetTol(krylov, settings_.tolerance);
      HYPRE_ParCSRBiCGSTABSetMaxIter(krylov, settings_.max_iterations);
      HYPRE_ParCSRBiCGSTABSetPrecond(krylov, precondition, precondition_setup, amg);
      HYPRE_ParCSRBiCGSTABSetup(krylov, parcsr, par_rhs, par_solution);
      // hypre's BiCGSTAB stops where it breaks down (a near-zero inner product, which an
      // iteration stalled near the tolerance can reach); Eigen's starts again from where it
      // stands, and so does this. (An attempt that broke down reports no iterations.)
      for (int attempt = 0; attempt < kBiCgStabAttempts; ++attempt) {
        const HYPRE_Int error = HYPRE_ParCSRBiCGSTABSolve(krylov, parcsr, par_rhs, par_solution);
        HYPRE_Int done = 0;
        HYPRE_ParCSRBiCGSTABGetNumIterations(krylov, &done);
        HYPRE_ParCSRBiCGSTABGetFinalRelativeResidualNorm(krylov, &residual);
        iterations += done;
        HYPRE_ClearAllErrors();
        if (error == 0 || residual <= settings_.tolerance) break;
      }
      HYPRE_ParCSRBiCGSTABDestroy(krylov);
    }
    if (n > 0) HYPRE_IJVectorGetValues(solution, n, rows.data(), x.data());
    SolveReport report;
    report.iterations = iterations;
    report.relative_residual = residual;
    report.converged = residual <= settings_.tolerance;

    if (amg != nullptr) HYPRE_BoomerAMGDestroy(amg);
    HYPRE_IJVectorDestroy(rhs);
    HYPRE_IJVectorDestroy(solution);
    HYPRE_IJMatrixDestroy(matrix);
    return report;
  }

 private:
  static HYPRE_IJVector vector(const Eigen::VectorXd& values, HYPRE_BigInt lower,
                               std::vector<HYPRE_BigInt>& rows) {
    const HYPRE_Int n = static_cast<HYPRE_Int>(values.size());
    HYPRE_IJVector v = nullptr;
    HYPRE_IJVectorCreate(MPI_COMM_WORLD, lower, lower + n - 1, &v);
    HYPRE_IJVectorSetObjectType(v, HYPRE_PARCSR);
    HYPRE_IJVectorInitialize(v);
    HYPRE_IJVectorSetValues(v, n, rows.data(), values.data());
    HYPRE_IJVectorAssemble(v);
    return v;
  }

  Method method_;
  Preconditioner preconditioner_;
  SolverSettings settings_;
};

// BoomerAMG on one process: the whole system is this process's rows.
class BoomerAmg final : public SparseSolver {
 public:
  explicit BoomerAmg(const SolverSettings& settings)
      : krylov_(Method::kConjugateGradient, Preconditioner::kBoomerAmg, settings) {}

  SolveReport solve(const SparseRows& a, const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    if (a.rows() == 0) {
      SolveReport empty;
      empty.converged = true;
      return empty;
    }
    return krylov_.solve(a, 0, b, x);
  }

 private:
  HypreKrylov krylov_;
};

}  // namespace

std::unique_ptr<SparseSolver> make_boomeramg(const SolverSettings& settings) {
  return std::make_unique<BoomerAmg>(settings);
}

std::unique_ptr<SplitSolver> make_hypre_split_solver(const std::string& name,
                                                     const SolverSettings& settings) {
  if (name == "boomeramg") {
    return std::make_unique<HypreKrylov>(Method::kConjugateGradient, Preconditioner::kBoomerAmg,
                                         settings);
  }
  if (name == "cg_diagonal") {
    return std::make_unique<HypreKrylov>(Method::kConjugateGradient, Preconditioner::kDiagonal,
                                         settings);
  }
  if (name == "bicgstab_diagonal") {
    return std::make_unique<HypreKrylov>(Method::kBiCgStab, Preconditioner::kDiagonal, settings);
  }
  return nullptr;
}

}  // namespace sluice
