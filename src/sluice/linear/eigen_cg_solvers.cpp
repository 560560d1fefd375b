#include "sluice/linear/eigen_cg_solvers.hpp"

#include <Eigen/IterativeLinearSolvers>

namespace sluice {

namespace {

// One of Eigen's iterative solvers behind the SparseSolver interface.
template <class EigenSolver>
class EigenIterative final : public SparseSolver {
 public:
  explicit EigenIterative(const SolverSettings& settings) {
    solver_.setTolerance(settings.tolerance);
    solver_.setMaxIterations(settings.max_iterations);
  }

  SolveReport solve(const SparseRows& a, const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    solver_.compute(a);
    SolveReport report;
    if (solver_.info() != Eigen::Success) return report;  // the preconditioner failed
    const Eigen::VectorXd guess = x;
    x = solver_.solveWithGuess(b, guess);
    report.iterations = static_cast<int>(solver_.iterations());
    if (!x.allFinite()) {
      // BiCGSTAB broke down (a step's denominator vanished, and NaN spread through x): one
      // more try from a zero guess, whose Krylov space differs from the warm start's.
      x = solver_.solveWithGuess(b, Eigen::VectorXd::Zero(b.size()));
      report.iterations += static_cast<int>(solver_.iterations());
    }
    report.relative_residual = solver_.error();
    report.converged = solver_.info() == Eigen::Success && x.allFinite();
    return report;
  }

 private:
  EigenSolver solver_;
};

// Lower|Upper: the whole matrix is used, which lets Eigen multiply on all threads; each row's
// product is summed by one thread, so the answer does not depend on the thread count.
template <class Preconditioner>
using EigenCg = EigenIterative<
    Eigen::ConjugateGradient<SparseRows, Eigen::Lower | Eigen::Upper, Preconditioner>>;

}  // namespace

std::unique_ptr<SparseSolver> make_eigen_bicgstab(const SolverSettings& settings) {
  return std::make_unique<
      EigenIterative<Eigen::BiCGSTAB<SparseRows, Eigen::DiagonalPreconditioner<double>>>>(settings);
}

std::unique_ptr<SparseSolver> make_eigen_cg(CgPreconditioner preconditioner,
                                            const SolverSettings& settings) {
  if (preconditioner == CgPreconditioner::kIncompleteCholesky) {
    return std::make_unique<EigenCg<Eigen::IncompleteCholesky<double, Eigen::Lower>>>(settings);
  }
  return std::make_unique<EigenCg<Eigen::DiagonalPreconditioner<double>>>(settings);
}

}  // namespace sluice
