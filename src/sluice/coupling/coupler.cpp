#include "sluice/coupling/coupler.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sluice/rigid/rigid_integrator.hpp"

namespace sluice {

Coupler::Coupler(MultibodySystem& system, std::size_t bodies, FluidExchange* fluid, bool subcycling,
                 const std::string& scheme)
    : system_(system),
      bodies_(bodies),
      fluid_(fluid),
      subcycling_(subcycling),
      scheme_(make_coupling_scheme(scheme)),
      motion_(bodies),
      fluid_force_(bodies, Vec3::Zero()),
      fluid_moment_(bodies, Vec3::Zero()) {
  update_motion(0);
  if (fluid_ && scheme_->fluid_solves_body_velocities()) fluid_->solve_body_velocities();
}

TimeStep Coupler::time_step(TimeStep fluid) {
  if (!fluid_ || subcycling_ || bodies_ == 0) return fluid;
  fluid.tighten(system_.solid_step(fluid.dt), "a contact's period (contact.subcycling is off)");
  return fluid;
}

// Each body's kinematics; over a step of dt > 0 the accelerations are the change of velocity.
void Coupler::update_motion(double dt) {
  for (std::size_t b = 0; b < bodies_; ++b) {
    const RigidBody& s = system_.bodies()[b].state;
    BodyKinematics& m = motion_[b];
    const Vec3 angular_velocity = s.angular_velocity();
    if (dt > 0) {
      m.acceleration = (s.velocity - m.velocity) / dt;
      m.angular_acceleration = (angular_velocity - m.angular_velocity) / dt;
    }
    m.position = s.position;
    m.orientation = s.orientation;
    m.velocity = s.velocity;
    m.angular_velocity = angular_velocity;
  }
}

int Coupler::exchanges(double dt) const {
  const double stiffness = fluid_ ? fluid_->boundary_stiffness() : 0;
  double lightest = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < bodies_; ++b) {
    if (!system_.bodies()[b].fixed) lightest = std::min(lightest, system_.bodies()[b].state.mass);
  }
  if (!(stiffness > 0) || std::isinf(lightest)) return 1;
  return static_cast<int>(std::ceil(dt * std::sqrt(stiffness / lightest) / kExchangeAngle - 1e-9));
}

int Coupler::exchange(double h, FluidLoads loads) {
  // In the solve, the fluid acts through it; its loads are for the output only.
  int substeps = 0;
  if (loads == FluidLoads::kInSolve && fluid_) {
    substeps = system_.advance(h, {}, {}, fluid_);
  } else if (loads == FluidLoads::kLeftOut) {
    substeps = system_.advance(h);
  } else {
    substeps = system_.advance(h, fluid_force_, fluid_moment_);
  }
  update_motion(h);
  if (fluid_) {
    fluid_->receive_body_motion(motion_);
    fluid_->advance_with_bodies(h);
  }
  return substeps;
}

void Coupler::take_solved_velocities(double dt) {
  const std::vector<Vec6> solved = fluid_->solved_body_velocities();
  if (solved.size() != bodies_) return;
  for (std::size_t b = 0; b < bodies_; ++b) {
    SystemBody& body = system_.bodies()[b];
    if (body.fixed) continue;
    RigidBody& s = body.state;
    const Vec3 velocity = solved[b].head<3>(), angular_velocity = solved[b].tail<3>();
    const Vec3 change = velocity - s.velocity;
    const Vec3 angular_change = angular_velocity - s.angular_velocity();
    // The bodies drifted over the step without the fluid's impulse. Its part of the drift, as
    // the kick-drift-kick step gives a load held over the step (h^2 F / 2m: half the velocity
    // it adds, over the step), so that a body the water holds at rest stays where the water
    // held it; without it the body sinks by g h^2 / 2 a step and the water it displaces is lost
    // at its faces.
    RigidBody shifted = s;
    shifted.velocity = 0.5 * change;
    shifted.angular_momentum = s.world_inertia() * (0.5 * angular_change);
    drift(shifted, dt);
    s.position = shifted.position;
    s.orientation = shifted.orientation;
    s.velocity = velocity;
    s.angular_momentum = s.world_inertia() * angular_velocity;
    s.enforce_locks();
    BodyKinematics& m = motion_[b];
    // The accelerations over the step: the advance's and the fluid's change together.
    if (dt > 0) {
      m.acceleration += change / dt;
      m.angular_acceleration += angular_change / dt;
    }
    m.position = s.position;
    m.orientation = s.orientation;
    m.velocity = s.velocity;
    m.angular_velocity = s.angular_velocity();
  }
}

void Coupler::collect_loads() {
  const std::vector<Wrench> loads = fluid_->body_loads(motion_);
  for (std::size_t b = 0; b < bodies_; ++b) {
    fluid_force_[b] = loads[b].force;
    fluid_moment_[b] = loads[b].moment;
  }
}

}  // namespace sluice
