// SPOOK, the regularised and stabilised velocity-level step of Lacoursière (Ph.D. thesis, Umeå
// University, 2007), as the constraint fluids of Bodin, Lacoursière & Servin (IEEE TVCG 18(3),
// 2012) use it. A constraint c(x) = 0 with compliance epsilon (the inverse of its stiffness)
// and relaxation time tau = d h (d steps of h) is met, over a step of h, by the velocities
// u after the step and the impulse gamma with
//   J u + Sigma gamma = -(4 Upsilon / h) c + Upsilon J v,
//   Upsilon = 1 / (1 + 4 d),  Sigma = 4 epsilon / (h^2 (1 + 4 d)),
// v the velocities at the step's start: a stiff spring-damper of the constraint, integrated
// implicitly, that removes a violation within about tau without the drift of a purely
// velocity-level step and without Baumgarte's oscillation.
#pragma once

#include "sluice/core/types.hpp"

namespace sluice {

struct SpookStep {
  Real violation_rate;  // 4 Upsilon / h: the target's factor of -c
  Real velocity_share;  // Upsilon: the target's factor of J v
  Real compliance;      // Sigma / epsilon = 4 / (h^2 (1 + 4 d))

  SpookStep(Real h, Real relaxation_steps)
      : violation_rate(4 / (h * (1 + 4 * relaxation_steps))),
        velocity_share(1 / (1 + 4 * relaxation_steps)),
        compliance(4 / (h * h * (1 + 4 * relaxation_steps))) {}

  // The velocity J u + Sigma gamma must reach, for a constraint c whose rate at the step's
  // start is J v.
  Real target(Real c, Real rate_at_start) const {
    return -violation_rate * c + velocity_share * rate_at_start;
  }
};

}  // namespace sluice
