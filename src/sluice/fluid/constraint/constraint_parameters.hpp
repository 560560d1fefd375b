// Parameters of the constraint-fluid model (seed 001's second method), read from the case's
// `model:` mapping. Defaults, meanings and sources are documented in docs/case-format.md.
#pragma once

#include "sluice/io/case_config.hpp"

namespace sluice {

struct ConstraintParameters {
  double h_over_dx = 1.3;  // the Wendland C2 kernel's h over the spacing (support 2h)
  // Compliance of the density constraint per unit of pressure [1/Pa]: the fluid is as
  // compressible as a liquid of bulk modulus 1 / compliance (default: water's, 2.2 GPa).
  double compliance = 1 / 2.2e9;
  double relaxation = 3;  // SPOOK's tau in time steps (d = tau / h)
  // Unilateral (default): a constraint only pushes (pressure >= 0), so a particle at the free
  // surface, short of neighbours, may leave it; bilateral also pulls (a fluid with tension).
  bool unilateral = true;
  // Viscosity constraints (viscosity_constraints.hpp): the kinematic viscosity [m^2/s] whose
  // damping they apply; 0 turns them off. They damp the particles' disordered motion, which
  // nothing else does (the density constraints hold divergence only).
  double viscosity = 1e-3;
  double time_step = 0;      // a fixed step [s]; 0 = cfl dx / the fastest speed
  double cfl = 0.15;         // of a spacing a particle may move in a step
  double max_speed = 0;      // the speed scale [m/s]; 0 = the free-fall speed sqrt(2 g H)
  int max_iterations = 100;  // of the one solve (fluid and bodies)
  double tolerance = 1e-3;   // of the one solve's residual [m/s]
  // Where the complementarity solve runs: the host, or the emulated device's copy of the
  // problem (ccp/device_ccp_problem.hpp), which gives the same answer to the bit.
  bool emulated_device = false;
};

ConstraintParameters read_constraint_parameters(const io::CaseConfig& config);

// The case as the constraint model needs it: the complementarity contact method (an input
// error when the case asks for the penalty one), and the model's iterations and tolerance for
// the one solve.
void prepare_constraint_case(io::CaseConfig& config);

}  // namespace sluice
