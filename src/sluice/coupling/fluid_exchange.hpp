// What the coupler exchanges with a fluid, whatever its discretisation: the bodies' motion in,
// the fluid's force and moment on each body out, and, in the monolithic scheme, constraints.
#pragma once

#include <vector>

#include "sluice/coupling/body_motion.hpp"
#include "sluice/ccp/constraint_row.hpp"

namespace sluice {

// Explicit co-simulation holds the fluid's loads over the bodies' sub-steps; in the
// monolithic scheme the fluid also contributes velocity constraints that the bodies' solver
// meets at every sub-step, together with whatever else binds the bodies.
enum class CouplingScheme { kCoSimulation, kMonolithic };

class FluidExchange {
 public:
  virtual ~FluidExchange() = default;
  virtual CouplingScheme scheme() const { return CouplingScheme::kCoSimulation; }
  // The monolithic scheme's rows for the coming step, from the bodies' motion now.
  virtual void body_constraints(const std::vector<BodyKinematics>& /*motion*/,
                                std::vector<ConstraintRow>& /*rows*/) const {}
  // The bodies have moved: the fluid places its boundary on them.
  virtual void receive_body_motion(const std::vector<BodyKinematics>& motion) = 0;
  // After receive_body_motion at the end of each exchange of length dt: a fluid that moves
  // its particles with the bodies (rather than before them) does so here.
  virtual void advance_with_bodies(double /*dt*/) {}
  // The stiffness [N/m] of the springs by which the fluid's boundary holds a body's particle
  // (penalty-sph), 0 when its loads are not springs. A step then holds as many exchanges as
  // keep the lightest free body stable on one such spring, its load held between them.
  virtual double boundary_stiffness() const { return 0; }
  // The fluid's force and moment (about the centre of mass) on each body, from its last force
  // evaluation.
  virtual std::vector<Wrench> body_loads(const std::vector<BodyKinematics>& motion) const = 0;
};

}  // namespace sluice
