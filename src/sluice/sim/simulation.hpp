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

// What a run asks of a simulation, whatever its dimension (sim/case_run.hpp).
class SteppedSimulation {
 public:
  virtual ~SteppedSimulation() = default;
  virtual void step(double until) = 0;
  virtual TimeStep next_time_step() = 0;
  virtual const TimeStep& last_stable_step() const = 0;
  virtual const StepClock& clock() const = 0;
  double time() const { return clock().time; }
  virtual bool has_model() const = 0;
  virtual const FluidSystem& fluid() const = 0;
  virtual FluidSystem& fluid() = 0;
  virtual const RigidBodies& bodies() const = 0;
  virtual RigidBodies& bodies() = 0;
  virtual const Coupler& coupler() const = 0;
  virtual StageTimers& timers() = 0;
  virtual const io::CaseConfig& config() const = 0;
  virtual void archive_state(StateArchive& a) = 0;
  virtual std::string bodies_division() const = 0;
  virtual int body_islands() const = 0;
  virtual int bodies_advanced_here() const = 0;
};

template <int D>
class Simulation final : public SteppedSimulation {
 public:
  // Builds the bodies (the case's and those its model adds), the fluid (the model the case
  // names among `models`, with what the process lends it: `services`) and the coupling from a
  // validated case (throws InputError).
  Simulation(const io::CaseConfig& config, const ModelRegistry& models,
             const ModelServices& services = {});
  explicit Simulation(const io::CaseConfig& config, const ModelServices& services = {})
      : Simulation(config, shipped_models<D>(), services) {}

  // Advances by one step of the model's stable size, clipped so as not to pass `until`.
  void step(double until) override;
  // The stable step from the present state, and what limits it.
  TimeStep next_time_step() override;
  // The stable step the last step() found (before clipping to `until`).
  const TimeStep& last_stable_step() const override { return last_step_; }

  const StepClock& clock() const override { return clock_; }
  // A case of bodies alone has no fluid model (its fluid draws the bodies' particles).
  bool has_model() const override { return config_.has_fluid(); }
  const FluidSystem& fluid() const override { return *fluid_; }
  FluidSystem& fluid() override { return *fluid_; }
  const RigidBodies& bodies() const override { return *bodies_; }
  RigidBodies& bodies() override { return *bodies_; }
  const Coupler& coupler() const override { return coupler_; }
  const StageTimers& timers() const { return timers_; }
  StageTimers& timers() override { return timers_; }
  const io::CaseConfig& config() const override { return config_; }  // with the model's bodies

  // Checkpoints: the clock, the bodies, the coupling and the fluid, written or read back.
  void archive_state(StateArchive& a) override;
  const Communicator& ranks() const { return ranks_; }
  // How the ranks share the bodies' advance: a line for the run's start ("" on one rank or
  // without bodies), and the islands of the last step (0 where every rank advances them all).
  std::string bodies_division() const override;
  int body_islands() const override { return sharing_ ? sharing_->islands() : 0; }
  int bodies_advanced_here() const override {
    return sharing_ ? sharing_->bodies_advanced_here() : 0;
  }

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
