// APGD (Mazhar, Heyn, Negrut & Tasora, ACM TOG 34(3), 2015, Algorithm 1): Nesterov's
// accelerated projected gradient on the CCP's quadratic program. Each iteration: the gradient
// at the extrapolated point y, a projected step of 1/L from it, the step halved (L doubled)
// until f falls below its quadratic model at y, the momentum update, a restart of the momentum
// when the step went uphill, and L relaxed by 0.9 for the next iteration. The best iterate
// (smallest residual) is returned. Two products with N an iteration.
// Unlike the paper, the iteration runs in the metric of N's diagonal W (each row's inverse
// effective mass; one value per cone, so projections are unchanged): steps are W^-1 g / L and
// the model's quadratic term is L |d|_W^2 / 2. A body a thousand times heavier than the
// spheres about it (a box floating on a granular pool) then does not slow every row down.
#include "sluice/ccp/ccp_iterations.hpp"
#include "sluice/ccp/host_ccp_space.hpp"

namespace sluice {

CcpResult solve_apgd(CcpProblem& problem, const CcpSettings& settings, BodyVelocities& velocities) {
  HostCcpSpace space{problem, velocities};
  return ccp_iterations::apgd(space, settings);
}

}  // namespace sluice
