// A simulation: the case's bodies, its fluid, the coupler between them, and the step as a list
// of named, timed stages.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sluice/core/stage_timer.hpp"
#include "sluice/coupling/coupler.hpp"
#include "sluice/fluid/fluid_system.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/models/shipped_models.hpp"
#include "sluice/parallel/communicator.hpp"
#include "sluice/sim/island_sharing.hpp"
#include "sluice/sim/rigid_bodies.hpp"

namespace sluice {

template <int D>
class Simulation {
 public:
  // Builds the bodies (the case's and those its model adds), the fluid (the model the case
  // names among `models`, with what the process lends it: `services`) and the coupling from a
  // validated case (throws InputError).
  Simulation(const io::CaseConfig& config, const ModelRegistry& models,
             const ModelServices& services = {});
  explicit Simulation(const io::CaseConfig& config, const ModelServices& services = {})
      : Simulation(config, shipped_models<D>(), services) {}

  // Advances by one step of the model's stable size, clipped so as not to pass `until`.
  void step(double until);
  // The stable step from the present state, and what limits it.
  TimeStep next_time_step();
  // The stable step the last step() found (before clipping to `until`).
  const TimeStep& last_stable_step() const { return last_step_; }

  const StepClock& clock() const { return clock_; }
  double time() const { return clock_.time; }
  // A case of bodies alone has no fluid model (its fluid draws the bodies' particles).
  bool has_model() const { return config_.has_fluid(); }
  const FluidSystem& fluid() const { return *fluid_; }
  FluidSystem& fluid() { return *fluid_; }
  const RigidBodies& bodies() const { return *bodies_; }
  const Coupler& coupler() const { return coupler_; }
  const StageTimers& timers() const { return timers_; }
  StageTimers& timers() { return timers_; }
  const io::CaseConfig& config() const { return config_; }  // with the model's bodies

  // Checkpoints: the clock, the bodies, the coupling and the fluid, written or read back.
  void archive_state(StateArchive& a);
  const Communicator& ranks() const { return ranks_; }
  // How the ranks share the bodies' advance: a line for the run's start ("" on one rank or
  // without bodies), and the islands of the last step (0 where every rank advances them all).
  std::string bodies_division() const;
  int body_islands() const { return sharing_ ? sharing_->islands() : 0; }
  int bodies_advanced_here() const { return sharing_ ? sharing_->bodies_advanced_here() : 0; }

 private:
  // The smallest of the ranks' steps, and its limit, on every rank.
  TimeStep agreed(TimeStep step);

  Communicator ranks_;
  std::string limit_;  // agreed()'s limit
  io::CaseConfig config_;
  std::unique_ptr<RigidBodies> bodies_;
  std::unique_ptr<IslandSharing> sharing_;  // a split run's, with ranks.bodies: islands
  std::unique_ptr<FluidSystem> fluid_;
  Coupler coupler_;
  StageList stages_;
  StageTimers timers_;
  std::vector<std::size_t> slots_;
  StepClock clock_;
  TimeStep last_step_;
};

}  // namespace sluice
