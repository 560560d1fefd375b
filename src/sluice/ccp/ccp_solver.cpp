#include "sluice/ccp/ccp_solver.hpp"

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

}  // namespace sluice
