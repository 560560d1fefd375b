#include "sluice/rigid/rigid_system.hpp"

#include <algorithm>
#include <cmath>

#include "sluice/rigid/rigid_integrator.hpp"

namespace sluice {

namespace {

std::uint8_t lock_bits(const RigidBody& body) {
  std::uint8_t bits = 0;
  for (int k = 0; k < 3; ++k) {
    if (body.locked_translation[k]) bits |= std::uint8_t(1 << k);
    if (body.locked_rotation[k]) bits |= std::uint8_t(1 << (k + 3));
  }
  return bits;
}

}  // namespace

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
  if (complementarity()) return dt;
  return interaction_ ? interaction_->stable_step(bodies_, dt) : dt;
}

void RigidSystem::solve_velocities(double h, bool contacts, CcpParticipant* participant,
                                   double stabilisation) {
  problem_.bodies.clear();
  for (const SystemBody& body : bodies_) {
    const RigidBody& s = body.state;
    if (body.fixed) {
      problem_.bodies.add(s.velocity, s.angular_velocity(), 0, Mat3::Zero(), 0);
    } else {
      problem_.bodies.add(s.velocity, s.angular_velocity(), 1 / s.mass, s.inverse_world_inertia(),
                          lock_bits(s));
    }
  }
  problem_.clear_groups();
  contact_rows_.clear();
  if (contacts && interaction_) {
    interaction_->contact_constraints(bodies_, h, velocity_step_.recovery_speed, contact_rows_);
    contact_rows_.drop_inert(problem_.bodies);
    problem_.add(contact_rows_);
  }
  // Joint rows come in the same order every step: the last step's impulses start them.
  std::vector<Real> last;
  for (const ConstraintRow& row : joint_rows_.rows()) last.push_back(row.impulse);
  joint_rows_.clear();
  for (const Joint& joint : joints_) {
    if (here(joint.a) || here(joint.b))
      add_joint_rows(joint, bodies_, h, stabilisation, joint_rows_);
  }
  joint_rows_.drop_inert(problem_.bodies);
  if (last.size() == joint_rows_.size()) {
    for (std::size_t k = 0; k < last.size(); ++k) joint_rows_.rows()[k].impulse = last[k];
  }
  problem_.add(joint_rows_);
  if (participant) participant->add_to_problem(problem_, h);

  auto solve = [&] {
    return participant ? participant->solve(problem_, velocity_step_.solver, velocities_)
                       : solve_ccp(problem_, velocity_step_.solver, velocities_);
  };
  CcpResult result = solve();
  for (int k = 0; k < velocity_step_.slip_iterations; ++k) {
    if (contact_rows_.correct_slip(velocities_) <= velocity_step_.solver.tolerance) break;
    const int before = result.iterations;
    result = solve();
    result.iterations += before;
  }
  ++totals_.solves;
  totals_.iterations += result.iterations;
  totals_.most_iterations = std::max(totals_.most_iterations, result.iterations);
  totals_.residual_sum += result.residual;
  totals_.largest_residual = std::max(totals_.largest_residual, result.residual);
  if (contacts && interaction_) interaction_->remember_contact_impulses(contact_rows_);

  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    if (!moves(b)) continue;
    RigidBody& s = bodies_[b].state;
    s.velocity = velocities_.linear[b];
    s.angular_momentum = s.world_inertia() * velocities_.angular[b];
    s.enforce_locks();
  }
  if (participant) participant->take_solution(problem_, velocities_, h);
}

int RigidSystem::advance(double dt, const std::vector<Vec3>& force, const std::vector<Vec3>& torque,
                         CcpParticipant* participant) {
  if (complementarity()) {
    advance_complementarity(dt, force, torque, participant);
    return 1;
  }
  const int substeps = static_cast<int>(std::ceil(dt / solid_step(dt) - 1e-9));
  const double h = dt / substeps;
  const std::size_t n = bodies_.size();
  if (sharing_) {
    here_ = sharing_->bodies_here(bodies_, joints_, interaction_, dt);
    if (interaction_) interaction_->evaluate_only(here_);
  }
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
      if (moves(b)) kick(bodies_[b].state, total_force(b), total_torque(b), 0.5 * h);
    }
    // Velocity constraints act on the velocity the bodies drift with, so that they hold the
    // positions too.
    if (has_velocity_rows(participant)) {
      solve_velocities(h, false, participant, velocity_step_.stabilisation);
    }
    for (std::size_t b = 0; b < n; ++b) {
      if (moves(b)) drift(bodies_[b].state, h);
    }
    // The dashpots see the velocities predicted to the end of the sub-step (with the forces
    // of the last evaluation), not the half-step ones, which would lag by h/2.
    for (std::size_t b = 0; b < n; ++b) {
      half[b] = bodies_[b].state;
      if (moves(b)) kick(bodies_[b].state, total_force(b), total_torque(b), 0.5 * h);
    }
    evaluate_interaction(h);
    for (std::size_t b = 0; b < n; ++b) bodies_[b].state = half[b];
    for (std::size_t b = 0; b < n; ++b) {
      if (moves(b)) kick(bodies_[b].state, total_force(b), total_torque(b), 0.5 * h);
    }
    // The last half kick leaves the joints: the velocities kept (which a fluid sees, and whose
    // change it takes for the bodies' acceleration) are put back on them.
    if (!joints_.empty()) solve_velocities(h, false, nullptr, 0.0);
    ++substeps_;
  }
  if (sharing_) sharing_->gather(bodies_, interaction_force_, interaction_torque_, interaction_);
  time_ += dt;
  return substeps;
}

void RigidSystem::advance_complementarity(double h, const std::vector<Vec3>& force,
                                          const std::vector<Vec3>& torque,
                                          CcpParticipant* participant) {
  // Prescribed bodies move to the step's end; the free ones predict their velocities.
  for (std::size_t b = 0; b < bodies_.size(); ++b) {
    if (bodies_[b].prescribed) bodies_[b].prescribed(time_ + h, bodies_[b].state);
    if (bodies_[b].fixed) continue;
    Vec3 f = bodies_[b].state.mass * gravity_;
    if (b < force.size()) f += force[b];
    kick(bodies_[b].state, f, b < torque.size() ? torque[b] : Vec3::Zero(), h);
  }
  solve_velocities(h, true, participant, velocity_step_.stabilisation);
  for (SystemBody& body : bodies_) {
    if (!body.fixed) drift(body.state, h);
  }
  // The contacts' impulses over the step, as forces, for the output.
  std::fill(interaction_force_.begin(), interaction_force_.end(), Vec3::Zero());
  std::fill(interaction_torque_.begin(), interaction_torque_.end(), Vec3::Zero());
  for (const ConstraintRow& r : contact_rows_.rows()) {
    if (r.a != ConstraintRow::kWorld) {
      interaction_force_[r.a] += r.impulse / h * r.linear_a;
      interaction_torque_[r.a] += r.impulse / h * r.angular_a;
    }
    if (r.b != ConstraintRow::kWorld) {
      interaction_force_[r.b] += r.impulse / h * r.linear_b;
      interaction_torque_[r.b] += r.impulse / h * r.angular_b;
    }
  }
  time_ += h;
  ++substeps_;
}

RigidSystemEnergy RigidSystem::energy() const {
  RigidSystemEnergy e;
  for (const SystemBody& body : bodies_) {
    if (body.fixed) continue;
    e.kinetic += body.state.kinetic_energy();
    e.potential -= body.state.mass * gravity_.dot(body.state.position);
  }
  e.elastic = interaction_ ? interaction_->stored_energy() : 0;  // cones store none
  return e;
}

void RigidSystem::archive_state(StateArchive& a) {
  a.section("rigid_system");
  a.expect(std::uint64_t(bodies_.size()), "number of bodies and walls");
  for (SystemBody& body : bodies_) a(body.state);
  a(time_, substeps_, interaction_force_, interaction_torque_, joint_rows_);
  a(totals_.solves, totals_.iterations, totals_.most_iterations, totals_.residual_sum,
    totals_.largest_residual);
}

}  // namespace sluice
