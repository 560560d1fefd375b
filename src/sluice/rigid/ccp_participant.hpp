// Something that joins the rigid bodies' velocity-level step with bodies and constraints of
// its own: in the monolithic coupling scheme, a fluid (a granular fluid's spheres and their
// contacts with each other, the walls and the bodies; or rows on the bodies alone).
#pragma once

#include "sluice/ccp/ccp_solver.hpp"

namespace sluice {

class CcpParticipant {
 public:
  virtual ~CcpParticipant() = default;
  // Adds its bodies after those already in `problem` (the rigid system's, at their predicted
  // velocities, indexed as the system's) and its groups, for a step of dt. The groups must
  // outlive the solve.
  virtual void add_to_problem(CcpProblem& /*problem*/, double /*dt*/) {}
  // Solves the step's problem, where the participant's work runs (its device); on the host by
  // default.
  virtual CcpResult solve(CcpProblem& problem, const CcpSettings& settings,
                          BodyVelocities& velocities) {
    return solve_ccp(problem, settings, velocities);
  }
  // After the solve: its bodies' velocities are in `velocities`, at the indices it gave them;
  // it moves them over dt.
  virtual void take_solution(const CcpProblem& /*problem*/, const BodyVelocities& /*velocities*/,
                             double /*dt*/) {}
};

}  // namespace sluice
