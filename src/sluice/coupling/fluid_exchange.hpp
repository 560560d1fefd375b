// What the coupler exchanges with a fluid, whatever its discretisation: the bodies' motion in,
// the fluid's force and moment on each body out, and, in the monolithic scheme, constraints; in
// the projection scheme, the bodies' velocities the fluid solved.
#pragma once

#include <vector>

#include "sluice/coupling/body_motion.hpp"
#include "sluice/rigid/ccp_participant.hpp"

namespace sluice {

// In the monolithic scheme (coupling_scheme.hpp) the fluid joins the bodies' velocity-level
// step (rigid/ccp_participant.hpp): rows on the bodies, or bodies and contacts of its own (a
// granular fluid's spheres), met in every solve together with whatever else binds the bodies.
class FluidExchange : public CcpParticipant {
 public:
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
  // evaluation. Monolithic: what its constraints exerted over the last step, for the output
  // only (the solve applied it).
  virtual std::vector<Wrench> body_loads(const std::vector<BodyKinematics>& motion) const = 0;

  // The projection scheme: the bodies advance without the fluid's loads, and the fluid solves
  // their velocities with its pressure, through their joined mobility
  // (BodyGeometry::joined_mobility). The coupler of that scheme calls this once, before the
  // first step; a fluid that cannot is not offered the scheme (its registry entry).
  virtual void solve_body_velocities() {}
  // Then, after each step's pressure solve: each body's velocity (linear, then angular) as
  // the fluid solved it, to give the body; empty before the first solve.
  virtual std::vector<Vec6> solved_body_velocities() const { return {}; }
};

}  // namespace sluice
