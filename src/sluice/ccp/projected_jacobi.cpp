// Projected Jacobi (Tasora & Anitescu, Comput. Methods Appl. Mech. Engrg. 200, 2011): every
// block steps against its gradient scaled by its own inverse effective mass, all at once,
// under-relaxed by omega, then projected: gamma <- P(gamma - omega g / diag(N)). One product
// with N an iteration; the reference APGD is compared with.
#include <cmath>
#include <limits>

#include "sluice/ccp/ccp_solver.hpp"
#include "sluice/ccp/ccp_vectors.hpp"

namespace sluice {

CcpResult solve_projected_jacobi(CcpProblem& problem, const CcpSettings& settings,
                                 BodyVelocities& velocities) {
  using namespace ccp_vectors;
  const std::size_t n = problem.size();
  std::vector<Real> gamma(n), g(n), diag(n), best(n), scratch;
  CcpResult out;
  if (n == 0) {
    problem.gradient(gamma, g, velocities);
    return out;
  }
  problem.diagonal(diag);
  const Real alpha = residual_alpha(diag);
  problem.warm_start(gamma);
  problem.project(gamma);
  Real best_residual = std::numeric_limits<Real>::infinity();
  for (out.iterations = 1; out.iterations <= settings.max_iterations; ++out.iterations) {
    problem.gradient(gamma, g, velocities);
    const Real residual = problem.residual(gamma, g, alpha, scratch);
    if (residual < best_residual) {
      best_residual = residual;
      best = gamma;
    }
    if (residual < settings.tolerance) break;
    exec::Default::for_each_light(n, [&](std::size_t i) {
      if (diag[i] > 0) gamma[i] -= settings.jacobi_relaxation * g[i] / diag[i];
    });
    problem.project(gamma);
  }
  return finish_ccp(problem, best, best_residual, out.iterations, settings, g, velocities);
}

}  // namespace sluice
