// A group of a cone complementarity problem's unknowns: impulses of one kind (joint rows,
// contacts of rigid bodies, a granular fluid's sphere contacts), each group storing them its
// own way. The problem (ccp_problem.hpp) sees only what the solvers need, each a pass over the
// group: the rows' velocities D^T u less their targets, the bodies' velocity change
// M^-1 D gamma, the projection onto the group's sets (cones, bounds), and the diagonal of
// D^T M^-1 D.
#pragma once

#include <span>

#include "sluice/ccp/ccp_bodies.hpp"

namespace sluice {

class ConstraintGroup {
 public:
  virtual ~ConstraintGroup() = default;
  // The number of unknowns (rows).
  virtual std::size_t size() const = 0;
  // out = D^T u - target: each row's velocity for body velocities u, less the velocity the row
  // asks for (the gradient of the problem's objective, in m/s or rad/s).
  virtual void row_velocities(const BodyVelocities& u, std::span<Real> out) const = 0;
  // out += E gamma for a group of compliant rows (regularised, as a constraint fluid's: the
  // problem's matrix is then D^T M^-1 D + E, E diagonal); none by default.
  virtual void add_compliance(std::span<const Real> /*gamma*/, std::span<Real> /*out*/) const {}
  // u += M^-1 D gamma, in an order that does not depend on the number of threads.
  virtual void apply_impulses(const CcpBodies& bodies, std::span<const Real> gamma,
                              BodyVelocities& u) const = 0;
  // gamma onto the group's feasible set, in place.
  virtual void project(std::span<Real> gamma) const = 0;
  // out = the diagonal of D^T M^-1 D + E (each row's inverse effective mass; a cone's three rows
  // take the same, so that a step scaled by it keeps the cone's shape).
  virtual void diagonal(const CcpBodies& bodies, std::span<Real> out) const = 0;
  // The impulses to start from (the last step's, where the group knows them), and the
  // solution handed back.
  virtual void warm_start(std::span<Real> gamma) const = 0;
  virtual void store(std::span<const Real> gamma) = 0;
};

}  // namespace sluice
