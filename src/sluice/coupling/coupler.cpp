#include "sluice/coupling/coupler.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

int Coupler::exchange(double h, bool in_solve) {
  // In the solve, the fluid acts through it; its loads are for the output only.
  const int substeps = in_solve && fluid_ ? system_.advance(h, {}, {}, fluid_)
                                          : system_.advance(h, fluid_force_, fluid_moment_);
  update_motion(h);
  if (fluid_) {
    fluid_->receive_body_motion(motion_);
    fluid_->advance_with_bodies(h);
  }
  return substeps;
}

void Coupler::collect_loads() {
  const std::vector<Wrench> loads = fluid_->body_loads(motion_);
  for (std::size_t b = 0; b < bodies_; ++b) {
    fluid_force_[b] = loads[b].force;
    fluid_moment_[b] = loads[b].moment;
  }
}

}  // namespace sluice
