#include "sluice/sim/simulation.hpp"

#include <algorithm>

#include "sluice/exec/policy.hpp"
#include "sluice/sim/particle_builder.hpp"

namespace sluice {

namespace {

template <int D>
std::unique_ptr<FluidModel<D>> model_for(const io::CaseConfig& config) {
  return config.has_fluid() ? make_fluid_model<D>(config) : nullptr;
}

// Without fluid, bodies and walls still get a neighbour grid (unused) of two spacings.
template <int D>
Real radius_for(const FluidModel<D>* model, const io::CaseConfig& config) {
  return model ? model->interaction_radius() : 2 * config.spacing;
}

}  // namespace

template <int D>
Simulation<D>::Simulation(const io::CaseConfig& config)
    : config_(config),
      model_(model_for<D>(config)),
      bodies_(std::make_unique<RigidBodies>(
          config, wall_layers(radius_for<D>(model_.get(), config), config.spacing))),
      state_(build_state<D>(config, radius_for<D>(model_.get(), config), *bodies_)) {
  std::vector<std::unique_ptr<ParticleStage<D>>> before, after;
  if (model_) {
    model_->initialize(state_);
    model_->append_stages(before, after);
  }
  stages_ = std::move(before);
  if (!bodies_->empty()) {
    stages_.push_back(
        make_stage<ParticleState<D>>("bodies", [this](ParticleState<D>& s) { move_bodies(s); }));
  }
  if (model_) {
    // The engine's own stage: sort particles by cell so neighbours sit close in memory.
    stages_.push_back(make_stage<ParticleState<D>>("neighbours", [this](ParticleState<D>& s) {
      s.cells.sort(s.particles.position, order_);
      s.particles.reorder(order_);
    }));
  }
  for (auto& stage : after) stages_.push_back(std::move(stage));
  if (model_ && !bodies_->empty()) {
    stages_.push_back(make_stage<ParticleState<D>>(
        "body_loads", [this](ParticleState<D>& s) { sum_body_loads(s); }));
    sum_body_loads(state_);
  }
  for (const auto& stage : stages_) slots_.push_back(timers_.slot(stage->name()));
}

template <int D>
double Simulation<D>::next_time_step() {
  if (model_) {
    const double dt = model_->next_time_step(state_);
    // Without sub-cycling, the fluid waits for the solid (C6's reference).
    if (!config_.contact.subcycling && !bodies_->empty()) return bodies_->solid_step(dt);
    return dt;
  }
  // Bodies alone: the multibody system sub-cycles within this step as contacts require.
  return std::min({config_.output_interval, config_.body_interval, 1e-3});
}

template <int D>
void Simulation<D>::move_bodies(ParticleState<D>& s) {
  bodies_->advance(s.dt);
  auto& ps = s.particles;
  exec::Default::for_each(ps.size(), [&](std::size_t i) {
    const std::int32_t k = ps.body_point[i];
    if (k < 0) return;
    ps.position[i] = from_3d<D>(bodies_->point_position(k));
    ps.velocity[i] = from_3d<D>(bodies_->point_velocity(k));
    s.body_point_acceleration[k] = bodies_->point_acceleration(k);
  });
}

// The fluid's force on each body point, summed per body into a force and a moment about the
// centre of mass.
template <int D>
void Simulation<D>::sum_body_loads(const ParticleState<D>& s) {
  point_force_.assign(bodies_->points().size(), Vec3::Zero());
  model_->body_point_forces(s, point_force_);
  std::vector<Vec3> force(bodies_->count(), Vec3::Zero()), moment(bodies_->count(), Vec3::Zero());
  for (std::size_t k = 0; k < point_force_.size(); ++k) {
    const std::size_t b = bodies_->points()[k].body;
    force[b] += point_force_[k];
    moment[b] += (bodies_->point_position(k) - bodies_->state(b).position).cross(point_force_[k]);
  }
  bodies_->set_fluid_loads(std::move(force), std::move(moment));
}

template <int D>
void Simulation<D>::step(double until) {
  double dt = next_time_step();
  // Stretch or shorten the last steps slightly so that the run ends exactly at `until`.
  const double remaining = until - state_.time;
  if (remaining < 1.5 * dt) dt = remaining <= dt * (1 + 1e-9) ? remaining : 0.5 * remaining;
  state_.dt = dt;
  for (std::size_t k = 0; k < stages_.size(); ++k) {
    timers_.time(slots_[k], [&] { stages_[k]->run(state_); });
  }
  state_.time += dt;
  ++state_.step;
}

template class Simulation<2>;
template class Simulation<3>;

}  // namespace sluice
