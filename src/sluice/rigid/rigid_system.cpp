#include "sluice/rigid/rigid_system.hpp"

#include <algorithm>
#include <cmath>

#include "sluice/rigid/constraint_solver.hpp"
#include "sluice/rigid/rigid_integrator.hpp"

namespace sluice {

std::size_t RigidSystem::add(SystemBody body) {
  bodies_.push_back(std::move(body));
  interaction_force_.assign(bodies_.size(), Vec3::Zero());
  interaction_torque_.assign(bodies_.size(), Vec3::Zero());
  return bodies_.size() - 1;
}

void RigidSystem::evaluate_interaction(double dt) {
  std::fill(interaction_force_.begin(), interaction_force_.end(), Vec3::Zero());
  std::fill(interaction_torque_.begin(), interaction_torque_.end(), Vec3::Zero());
  if (interaction_) interaction_->evaluate(bodies_, dt, interaction_force_, interaction_torque_);
}

double RigidSystem::solid_step(double dt) {
  return interaction_ ? interaction_->stable_step(bodies_, dt) : dt;
}

int RigidSystem::advance(double dt, const std::vector<Vec3>& force, const std::vector<Vec3>& torque,
                         std::vector<ConstraintRow>* rows) {
  const int substeps = static_cast<int>(std::ceil(dt / solid_step(dt) - 1e-9));
  const double h = dt / substeps;
  const std::size_t n = bodies_.size();
  if (substeps_ == 0) evaluate_interaction(0);
  auto total_force = [&](std::size_t b) {
    Vec3 f = bodies_[b].state.mass * gravity_ + interaction_force_[b];
    if (b < force.size()) f += force[b];
    return f;
  };
  auto total_torque = [&](std::size_t b) {
    Vec3 t = interaction_torque_[b];
    if (b < torque.size()) t += torque[b];
    return t;
  };
  std::vector<RigidBody> half(n);
  for (int s = 0; s < substeps; ++s) {
    for (std::size_t b = 0; b < n; ++b) {
      if (bodies_[b].prescribed) bodies_[b].prescribed(time_ + (s + 1) * h, bodies_[b].state);
      if (!bodies_[b].fixed) kick(bodies_[b].state, total_force(b), total_torque(b), 0.5 * h);
    }
    // Velocity constraints act on the velocity the bodies drift with, so that they hold the
    // positions too.
    if (rows && !rows->empty()) solve_constraints(bodies_, *rows);
    for (std::size_t b = 0; b < n; ++b) {
      if (!bodies_[b].fixed) drift(bodies_[b].state, h);
    }
    // The dashpots see the velocities predicted to the end of the sub-step (with the forces
    // of the last evaluation), not the half-step ones, which would lag by h/2.
    for (std::size_t b = 0; b < n; ++b) {
      half[b] = bodies_[b].state;
      if (!bodies_[b].fixed) kick(bodies_[b].state, total_force(b), total_torque(b), 0.5 * h);
    }
    evaluate_interaction(h);
    for (std::size_t b = 0; b < n; ++b) bodies_[b].state = half[b];
    for (std::size_t b = 0; b < n; ++b) {
      if (!bodies_[b].fixed) kick(bodies_[b].state, total_force(b), total_torque(b), 0.5 * h);
    }
    ++substeps_;
  }
  time_ += dt;
  return substeps;
}

RigidSystemEnergy RigidSystem::energy() const {
  RigidSystemEnergy e;
  for (const SystemBody& body : bodies_) {
    if (body.fixed) continue;
    e.kinetic += body.state.kinetic_energy();
    e.potential -= body.state.mass * gravity_.dot(body.state.position);
  }
  e.elastic = interaction_ ? interaction_->stored_energy() : 0;
  return e;
}

}  // namespace sluice
