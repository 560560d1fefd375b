#include "sluice/linear/boomeramg_solver.hpp"

#include "sluice/linear/hypre_session.hpp"

#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>
#include <mpi.h>

#include <numeric>
#include <stdexcept>

namespace sluice {

namespace {

class BoomerAmg final : public SparseSolver {
 public:
  explicit BoomerAmg(const SolverSettings& settings) : settings_(settings) {}

  SolveReport solve(const SparseRows& a, const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    if (settings_.hypre == nullptr)
      throw std::logic_error("boomeramg: made without the process's hypre session");
    settings_.hypre->start();
    const HYPRE_Int n = static_cast<HYPRE_Int>(a.rows());
    SolveReport report;
    if (n == 0) {
      report.converged = true;
      return report;
    }
    HYPRE_IJMatrix matrix = nullptr;
    HYPRE_IJMatrixCreate(MPI_COMM_WORLD, 0, n - 1, 0, n - 1, &matrix);
    HYPRE_IJMatrixSetObjectType(matrix, HYPRE_PARCSR);
    std::vector<HYPRE_Int> row_sizes(n);
    for (HYPRE_Int i = 0; i < n; ++i)
      row_sizes[i] = a.outerIndexPtr()[i + 1] - a.outerIndexPtr()[i];
    HYPRE_IJMatrixSetRowSizes(matrix, row_sizes.data());
    HYPRE_IJMatrixInitialize(matrix);
    std::vector<HYPRE_BigInt> rows(n);
    std::iota(rows.begin(), rows.end(), 0);
    HYPRE_IJMatrixSetValues(matrix, n, row_sizes.data(), rows.data(), a.innerIndexPtr(),
                            a.valuePtr());
    HYPRE_IJMatrixAssemble(matrix);
    HYPRE_ParCSRMatrix parcsr = nullptr;
    HYPRE_IJMatrixGetObject(matrix, reinterpret_cast<void**>(&parcsr));

    HYPRE_IJVector rhs = vector(b, rows);
    HYPRE_IJVector solution = vector(x, rows);
    HYPRE_ParVector par_rhs = nullptr, par_solution = nullptr;
    HYPRE_IJVectorGetObject(rhs, reinterpret_cast<void**>(&par_rhs));
    HYPRE_IJVectorGetObject(solution, reinterpret_cast<void**>(&par_solution));

    HYPRE_Solver pcg = nullptr, amg = nullptr;
    HYPRE_ParCSRPCGCreate(MPI_COMM_WORLD, &pcg);
    HYPRE_PCGSetTol(pcg, settings_.tolerance);
    HYPRE_PCGSetMaxIter(pcg, settings_.max_iterations);
    HYPRE_PCGSetTwoNorm(pcg, 1);  // |r| / |b| in the 2-norm, as Eigen's
    HYPRE_BoomerAMGCreate(&amg);
    HYPRE_BoomerAMGSetMaxIter(amg, 1);
    HYPRE_BoomerAMGSetTol(amg, 0.0);
    HYPRE_BoomerAMGSetPrintLevel(amg, 0);
    HYPRE_PCGSetPrecond(pcg, reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSolve),
                        reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSetup), amg);
    HYPRE_ParCSRPCGSetup(pcg, parcsr, par_rhs, par_solution);
    HYPRE_ParCSRPCGSolve(pcg, parcsr, par_rhs, par_solution);
    HYPRE_Int iterations = 0;
    HYPRE_Real residual = 0;
    HYPRE_PCGGetNumIterations(pcg, &iterations);
    HYPRE_PCGGetFinalRelativeResidualNorm(pcg, &residual);
    HYPRE_IJVectorGetValues(solution, n, rows.data(), x.data());
    report.iterations = iterations;
    report.relative_residual = residual;
    report.converged = residual <= settings_.tolerance;

    HYPRE_BoomerAMGDestroy(amg);
    HYPRE_ParCSRPCGDestroy(pcg);
    HYPRE_IJVectorDestroy(rhs);
    HYPRE_IJVectorDestroy(solution);
    HYPRE_IJMatrixDestroy(matrix);
    return report;
  }

 private:
  static HYPRE_IJVector vector(const Eigen::VectorXd& values, std::vector<HYPRE_BigInt>& rows) {
    const HYPRE_Int n = static_cast<HYPRE_Int>(values.size());
    HYPRE_IJVector v = nullptr;
    HYPRE_IJVectorCreate(MPI_COMM_WORLD, 0, n - 1, &v);
    HYPRE_IJVectorSetObjectType(v, HYPRE_PARCSR);
    HYPRE_IJVectorInitialize(v);
    HYPRE_IJVectorSetValues(v, n, rows.data(), values.data());
    HYPRE_IJVectorAssemble(v);
    return v;
  }

  SolverSettings settings_;
};

}  // namespace

std::unique_ptr<SparseSolver> make_boomeramg(const SolverSettings& settings) {
  return std::make_unique<BoomerAmg>(settings);
}

}  // namespace sluice
