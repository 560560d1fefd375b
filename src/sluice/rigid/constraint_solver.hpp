// Velocity-level constraints solved by projected Gauss-Seidel (Erleben 2007; the iteration of
// Chrono's and Bullet's sequential impulse solvers): each row in turn takes the impulse that
// meets its bias, clamped to its bounds, until the impulses settle. The bodies' velocities
// change by M^-1 J^T lambda.
#pragma once

#include <vector>

#include "sluice/rigid/body_interaction.hpp"
#include "sluice/ccp/constraint_row.hpp"

namespace sluice {

struct ConstraintSolution {
  int iterations = 0;
  double largest_change = 0;  // of an impulse in the last sweep [N s]
};

// Solves `rows` (impulses start from their `impulse`, warm) and applies the impulses to the
// free bodies' velocities and angular momenta. Stops when no impulse changes by more than
// `tolerance` in a sweep, or after `max_iterations` sweeps.
ConstraintSolution solve_constraints(std::vector<SystemBody>& bodies,
                                     std::vector<ConstraintRow>& rows, int max_iterations = 100,
                                     double tolerance = 1e-12);

}  // namespace sluice
