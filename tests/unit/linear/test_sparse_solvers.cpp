// Every sparse solver this build offers solves a 2D Poisson problem (5-point Laplacian plus a
// small diagonal shift) to its tolerance, from a cold and from a warm start; BiCGSTAB also one
// that is not symmetric.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <stdexcept>

#include "sluice/linear/hypre_session.hpp"
#include "sluice/linear/sparse_solver.hpp"

namespace sluice {
namespace {

// MPI starts once in a process: the test binary's hypre session lives as long as its tests,
// and stops after the last of them.
class HypreEnvironment : public ::testing::Environment {
 public:
  void TearDown() override { session.finish(); }
  HypreSession session;
};
HypreEnvironment* const hypre_environment =
    static_cast<HypreEnvironment*>(::testing::AddGlobalTestEnvironment(new HypreEnvironment));

// `upwind` > 0 adds a one-sided difference in i (a convection term): the matrix is then not
// symmetric.
SparseRows poisson(int side, double shift, double upwind = 0) {
  std::vector<Eigen::Triplet<double>> entries;
  const auto at = [side](int i, int j) { return i + side * j; };
  for (int j = 0; j < side; ++j) {
    for (int i = 0; i < side; ++i) {
      entries.emplace_back(at(i, j), at(i, j), 4 + shift + upwind);
      if (i > 0) entries.emplace_back(at(i, j), at(i - 1, j), -1 - upwind);
      if (i + 1 < side) entries.emplace_back(at(i, j), at(i + 1, j), -1);
      if (j > 0) entries.emplace_back(at(i, j), at(i, j - 1), -1);
      if (j + 1 < side) entries.emplace_back(at(i, j), at(i, j + 1), -1);
    }
  }
  SparseRows a(side * side, side * side);
  a.setFromTriplets(entries.begin(), entries.end());
  return a;
}

TEST(SparseSolvers, EachSolvesAPoissonProblem) {
  const SparseRows a = poisson(40, 1e-3);
  Eigen::VectorXd expected(a.rows());
  for (Eigen::Index k = 0; k < expected.size(); ++k) expected[k] = std::sin(0.01 * k) + 1;
  const Eigen::VectorXd b = a * expected;
  SolverSettings settings;
  settings.tolerance = 1e-10;
  settings.hypre = &hypre_environment->session;
  ASSERT_GE(sparse_solver_names().size(), 2u);
  for (const std::string& name : sparse_solver_names()) {
    SCOPED_TRACE(name);
    auto solver = make_sparse_solver(name, settings);
    ASSERT_NE(solver, nullptr);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(a.rows());
    const SolveReport cold = solver->solve(a, b, x);
    EXPECT_TRUE(cold.converged);
    EXPECT_LE(cold.relative_residual, settings.tolerance);
    EXPECT_LT((x - expected).norm() / expected.norm(), 1e-6);
    // From the answer itself: at most one iteration.
    const SolveReport warm = solver->solve(a, b, x);
    EXPECT_TRUE(warm.converged);
    EXPECT_LE(warm.iterations, 1);
  }
}

TEST(SparseSolvers, BicgstabSolvesASystemThatIsNotSymmetric) {
  const SparseRows a = poisson(40, 1e-3, 2.0);
  ASSERT_GT((SparseRows(a.transpose()) - a).norm(), 1.0);
  Eigen::VectorXd expected(a.rows());
  for (Eigen::Index k = 0; k < expected.size(); ++k) expected[k] = std::cos(0.02 * k) + 2;
  const Eigen::VectorXd b = a * expected;
  auto solver = make_sparse_solver("bicgstab_diagonal", SolverSettings{1e-10, 1000});
  ASSERT_NE(solver, nullptr);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(a.rows());
  const SolveReport report = solver->solve(a, b, x);
  EXPECT_TRUE(report.converged);
  EXPECT_LT((x - expected).norm() / expected.norm(), 1e-6);
}

// A warm start on which BiCGSTAB breaks down at its first step: r0 = b - A x0 = (0, 1) and
// A r0 = (1, 0), so r0 . A r0 = 0 divides the step. The solver starts again from zero, where
// r0 = b and r0 . A r0 = 1, and solves; the MPS pressure solve met such a step
// (docs/validation.md).
TEST(SparseSolvers, BicgstabStartsAgainFromZeroWhereTheWarmStartBreaksDown) {
  SparseRows a(2, 2);
  a.insert(0, 0) = 1;
  a.insert(0, 1) = 1;
  a.insert(1, 0) = -1;
  a.makeCompressed();
  const Eigen::Vector2d b(1, 1);
  auto solver = make_sparse_solver("bicgstab_diagonal", SolverSettings{1e-12, 100});
  Eigen::VectorXd x = Eigen::Vector2d(0, 1);
  const SolveReport report = solver->solve(a, b, x);
  EXPECT_TRUE(report.converged);
  ASSERT_TRUE(x.allFinite());
  EXPECT_NEAR(x[0], -1, 1e-9);  // A^-1 b = (-1, 2)
  EXPECT_NEAR(x[1], 2, 1e-9);
}

TEST(SparseSolvers, ReportsAFailureToConverge) {
  const SparseRows a = poisson(40, 1e-3);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(a.rows());
  SolverSettings settings;
  settings.tolerance = 1e-12;
  settings.max_iterations = 2;
  for (const std::string& name : {std::string("cg_diagonal")}) {
    auto solver = make_sparse_solver(name, settings);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(a.rows());
    const SolveReport r = solver->solve(a, b, x);
    EXPECT_FALSE(r.converged);
    EXPECT_GT(r.relative_residual, settings.tolerance);
  }
}

TEST(SparseSolvers, UnknownNameGivesNothing) {
  EXPECT_EQ(make_sparse_solver("no_such_solver", SolverSettings{}), nullptr);
}

// hypre's solver starts MPI and hypre through the session it is given, at its first solve;
// made without one it refuses to solve, rather than start MPI where nothing would stop it.
TEST(HypreSession, StartsAtTheFirstSolveAndAHypreSolverWithoutOneRefuses) {
  const std::vector<std::string> names = sparse_solver_names();
  if (std::find(names.begin(), names.end(), "boomeramg") == names.end())
    GTEST_SKIP() << "built without hypre";
  const SparseRows a = poisson(10, 1e-3);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(a.rows());
  Eigen::VectorXd x = Eigen::VectorXd::Zero(a.rows());
  auto alone = make_sparse_solver("boomeramg", SolverSettings{});
  EXPECT_THROW(alone->solve(a, b, x), std::logic_error);
  HypreSession& session = hypre_environment->session;
  auto with_session = make_sparse_solver("boomeramg", SolverSettings{1e-10, 100, &session});
  EXPECT_TRUE(with_session->solve(a, b, x).converged);
  EXPECT_TRUE(session.started());
  session.start();  // again: nothing
  EXPECT_TRUE(session.started());
}

}  // namespace
}  // namespace sluice
