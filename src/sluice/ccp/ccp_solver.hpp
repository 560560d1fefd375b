// Solvers of a cone complementarity problem, found by name (a case's
// `contact.complementarity.solver`): APGD, Nesterov's accelerated projected gradient with
// adaptive step and restart (Mazhar, Heyn, Negrut & Tasora, ACM TOG 34(3), 2015), and projected
// Jacobi (the fixed-point iteration of Tasora & Anitescu 2011), for comparison. Both start from
// the groups' warm start, stop at the residual tolerance (ccp_problem.hpp) or the iteration
// limit, hand the impulses back to the groups and return the bodies' velocities after them.
#pragma once

#include <string>
#include <vector>

#include "sluice/ccp/ccp_problem.hpp"

namespace sluice {

struct CcpSettings {
  std::string solver = "apgd";
  int max_iterations = 100;
  Real tolerance = 1e-4;         // of the residual [m/s]
  Real jacobi_relaxation = 0.3;  // omega of projected Jacobi: gamma -= omega g / diag(N)
};

struct CcpResult {
  int iterations = 0;
  Real residual = 0;  // of the impulses returned [m/s]
};

// The solvers' names, for messages.
std::vector<std::string> ccp_solver_names();

// Solves `problem` with the solver `settings.solver` names (std::invalid_argument for an
// unknown one); `velocities` receives the bodies' velocities after the impulses.
CcpResult solve_ccp(CcpProblem& problem, const CcpSettings& settings, BodyVelocities& velocities);

CcpResult solve_apgd(CcpProblem& problem, const CcpSettings& settings, BodyVelocities& velocities);
CcpResult solve_projected_jacobi(CcpProblem& problem, const CcpSettings& settings,
                                 BodyVelocities& velocities);

}  // namespace sluice
