// Projected Jacobi (Tasora & Anitescu, Comput. Methods Appl. Mech. Engrg. 200, 2011): every
// block steps against its gradient scaled by its own inverse effective mass, all at once,
// under-relaxed by omega, then projected: gamma <- P(gamma - omega g / diag(N)). One product
// with N an iteration; the reference APGD is compared with.
#include "sluice/ccp/ccp_iterations.hpp"
#include "sluice/ccp/host_ccp_space.hpp"

namespace sluice {

CcpResult solve_projected_jacobi(CcpProblem& problem, const CcpSettings& settings,
                                 BodyVelocities& velocities) {
  HostCcpSpace space{problem, velocities};
  return ccp_iterations::projected_jacobi(space, settings);
}

}  // namespace sluice
