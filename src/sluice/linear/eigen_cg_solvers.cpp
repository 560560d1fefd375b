#include "sluice/linear/eigen_cg_solvers.hpp"

#include <Eigen/IterativeLinearSolvers>

namespace sluice {

namespace {

// Lower|Upper: the whole matrix is used, which lets Eigen multiply on all threads; each row's
// product is summed by one thread, so the answer does not depend on the thread count.
template <class Preconditioner>
class EigenCg final : public SparseSolver {
 public:
  explicit EigenCg(const SolverSettings& settings) {
    cg_.setTolerance(settings.tolerance);
    cg_.setMaxIterations(settings.max_iterations);
  }

  SolveReport solve(const SparseRows& a, const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    cg_.compute(a);
    SolveReport report;
    if (cg_.info() != Eigen::Success) return report;  // the preconditioner failed
    x = cg_.solveWithGuess(b, x);
    report.iterations = static_cast<int>(cg_.iterations());
    report.relative_residual = cg_.error();
    report.converged = cg_.info() == Eigen::Success;
    return report;
  }

 private:
  Eigen::ConjugateGradient<SparseRows, Eigen::Lower | Eigen::Upper, Preconditioner> cg_;
};

// For the systems that are not symmetric (MPS with extrapolated wall pressures).
class EigenBicgstab final : public SparseSolver {
 public:
  explicit EigenBicgstab(const SolverSettings& settings) {
    solver_.setTolerance(settings.tolerance);
    solver_.setMaxIterations(settings.max_iterations);
  }

  SolveReport solve(const SparseRows& a, const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    solver_.compute(a);
    SolveReport report;
    if (solver_.info() != Eigen::Success) return report;
    x = solver_.solveWithGuess(b, x);
    report.iterations = static_cast<int>(solver_.iterations());
    report.relative_residual = solver_.error();
    report.converged = solver_.info() == Eigen::Success;
    return report;
  }

 private:
  Eigen::BiCGSTAB<SparseRows, Eigen::DiagonalPreconditioner<double>> solver_;
};

}  // namespace

std::unique_ptr<SparseSolver> make_eigen_bicgstab(const SolverSettings& settings) {
  return std::make_unique<EigenBicgstab>(settings);
}

std::unique_ptr<SparseSolver> make_eigen_cg(CgPreconditioner preconditioner,
                                            const SolverSettings& settings) {
  if (preconditioner == CgPreconditioner::kIncompleteCholesky) {
    return std::make_unique<EigenCg<Eigen::IncompleteCholesky<double, Eigen::Lower>>>(settings);
  }
  return std::make_unique<EigenCg<Eigen::DiagonalPreconditioner<double>>>(settings);
}

}  // namespace sluice
