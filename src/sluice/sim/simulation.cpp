#include "sluice/sim/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sluice/core/time_step.hpp"

namespace sluice {

template <int D>
Simulation<D>::Simulation(const io::CaseConfig& config, const ModelRegistry& models,
                          const ModelServices& services)
    : ranks_(services.ranks != nullptr ? *services.ranks : Communicator::alone()),
      config_(models.prepared(config)),
      bodies_(std::make_unique<RigidBodies>(config_)),
      fluid_(make_fluid_system<D>(config_, *bodies_, models, services)),
      coupler_(bodies_->system(), bodies_->count(), &fluid_->exchange(), config.contact.subcycling,
               models.coupling_scheme(config_)) {
  MultibodySystem& system = bodies_->system();
  if (ranks_.split() && config_.ranks.bodies == "islands" && bodies_->count() > 0 &&
      !system.rigid().complementarity()) {
    sharing_ = std::make_unique<IslandSharing>(ranks_);
    system.set_sharing(sharing_.get());
  }
  StageList before_bodies, after_bodies;
  fluid_->append_stages(before_bodies, after_bodies);
  stages_ = coupler_.assemble_step(std::move(before_bodies), std::move(after_bodies),
                                   !bodies_->empty(), has_model());
  for (const auto& stage : stages_) slots_.push_back(timers_.slot(stage->name()));
}

template <int D>
TimeStep Simulation<D>::next_time_step() {
  if (has_model()) return agreed(coupler_.time_step(fluid_->next_time_step()));
  // Bodies alone: the multibody system sub-cycles within this step as contacts require.
  TimeStep step;
  step.tighten(std::min({config_.output_interval, config_.body_interval, 1e-3}),
               "the output intervals (bodies alone sub-cycle within a step)");
  return step;
}

template <int D>
TimeStep Simulation<D>::agreed(TimeStep step) {
  if (!ranks_.split()) return step;
  // A NaN step (a rank gone wrong) is the smallest, so that its limit names the culprit.
  const double key = std::isnan(step.dt) ? -std::numeric_limits<double>::infinity() : step.dt;
  const double smallest = ranks_.min(key);
  limit_ = ranks_.broadcast(step.limit, ranks_.first_rank_where(key == smallest));
  step.dt =
      std::isinf(smallest) && smallest < 0 ? std::numeric_limits<double>::quiet_NaN() : smallest;
  step.limit = limit_.c_str();
  return step;
}

template <int D>
void Simulation<D>::step(double until) {
  last_step_ = next_time_step();
  // Equal steps that land exactly on `until` (an output's time or the end).
  const double dt = step_towards(until - clock_.time, last_step_.dt);
  clock_.dt = dt;
  if (has_model()) bodies_->absorb_waves(clock_.time, fluid_->observation());
  for (std::size_t k = 0; k < stages_.size(); ++k) {
    timers_.time(slots_[k], [&] { stages_[k]->run(clock_); });
  }
  clock_.time += dt;
  ++clock_.step;
}

template <int D>
std::string Simulation<D>::bodies_division() const {
  if (!ranks_.split() || bodies_->count() == 0) return "";
  if (sharing_) {
    return "bodies: each island of bodies in reach of each other (or joined) advanced by one "
           "rank";
  }
  return "bodies: every rank advances every body";
}

template <int D>
void Simulation<D>::archive_state(StateArchive& a) {
  a.section("clock");
  a(clock_.time, clock_.dt, clock_.step, last_step_.dt);  // its limit is named anew each step
  bodies_->archive_state(a);
  coupler_.archive_state(a);
  a.section("fluid");
  fluid_->archive_state(a);
}

template class Simulation<2>;
template class Simulation<3>;

}  // namespace sluice
