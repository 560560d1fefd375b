// Newton-Euler time stepping by splitting (Dullweber, Leimkuhler & McLachlan, J. Chem. Phys.
// 107, 1997): kicks by force and torque, a drift of the centre of mass, and the free rotation
// composed of exact rotations about the three principal axes (Strang splitting 1-2-3-2-1).
// Each part is exact, so the scheme is symplectic and time-reversible: in free flight the
// world angular momentum is conserved to round-off and the energy error stays bounded.
#pragma once

#include "sluice/rigid/rigid_body.hpp"

namespace sluice {

// v += dt F / m, L += dt T (then the locks).
void kick(RigidBody& body, const Vec3& force, const Vec3& torque, double dt);

// Moves the centre of mass with its velocity and turns the body freely for dt.
void drift(RigidBody& body, double dt);

// One kick-drift-kick step of length dt with the force and torque given by `load(body)`,
// evaluated after the drift (the first half kick uses `force`/`torque` from before).
template <class Load>
void step_rigid(RigidBody& body, Vec3& force, Vec3& torque, double dt, Load&& load) {
  kick(body, force, torque, 0.5 * dt);
  drift(body, dt);
  load(body, force, torque);
  kick(body, force, torque, 0.5 * dt);
}

}  // namespace sluice
