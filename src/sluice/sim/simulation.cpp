#include "sluice/sim/simulation.hpp"

#include "sluice/sim/particle_builder.hpp"

namespace sluice {

template <int D>
Simulation<D>::Simulation(const io::CaseConfig& config)
    : config_(config),
      model_(make_fluid_model<D>(config)),
      state_(build_state<D>(config, model_->interaction_radius())) {
  model_->initialize(state_);
  std::vector<std::unique_ptr<Stage<D>>> before, after;
  model_->append_stages(before, after);
  stages_ = std::move(before);
  // The engine's own stage: sort particles by cell so neighbours sit close in memory.
  stages_.push_back(make_stage<D>("neighbours", [this](SimulationState<D>& s) {
    s.cells.sort(s.particles.position, order_);
    s.particles.reorder(order_);
  }));
  for (auto& stage : after) stages_.push_back(std::move(stage));
  for (const auto& stage : stages_) slots_.push_back(timers_.slot(stage->name()));
}

template <int D>
void Simulation<D>::step(double until) {
  double dt = model_->next_time_step(state_);
  // Stretch or shorten the last steps slightly so that the run ends exactly at `until`.
  const double remaining = until - state_.time;
  if (remaining < 1.5 * dt) dt = remaining < dt ? remaining : 0.5 * remaining;
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
