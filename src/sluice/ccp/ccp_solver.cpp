#include "sluice/ccp/ccp_solver.hpp"

#include <algorithm>

#include <stdexcept>

namespace sluice {

std::vector<std::string> ccp_solver_names() {
  return {"apgd", "jacobi"};
}

CcpResult solve_ccp(CcpProblem& problem, const CcpSettings& settings, BodyVelocities& velocities) {
  if (settings.solver == "apgd") return solve_apgd(problem, settings, velocities);
  if (settings.solver == "jacobi") return solve_projected_jacobi(problem, settings, velocities);
  throw std::invalid_argument("unknown complementarity solver '" + settings.solver + "'");
}

CcpResult finish_ccp(CcpProblem& problem, const std::vector<Real>& best, Real residual,
                     int iterations, const CcpSettings& settings, std::vector<Real>& scratch,
                     BodyVelocities& velocities) {
  problem.gradient(best, scratch, velocities);
  problem.store(best);
  return {std::min(iterations, settings.max_iterations), residual};
}

}  // namespace sluice
