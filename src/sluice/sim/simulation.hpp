// A simulation: the state, the fluid model and the step as a list of named, timed stages.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sluice/core/stage_timer.hpp"
#include "sluice/fluid/fluid_model.hpp"
#include "sluice/fluid/particle_state.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/sim/rigid_bodies.hpp"

namespace sluice {

template <int D>
class Simulation {
 public:
  // Builds the model and the particles from a validated case (throws InputError).
  explicit Simulation(const io::CaseConfig& config);

  // Advances by one step of the model's stable size, clipped so as not to pass `until`.
  void step(double until);

  ParticleState<D>& state() { return state_; }
  const ParticleState<D>& state() const { return state_; }
  // A case of bodies alone has no fluid model.
  bool has_model() const { return model_ != nullptr; }
  const FluidModel<D>& model() const { return *model_; }
  const RigidBodies& bodies() const { return *bodies_; }
  const StageTimers& timers() const { return timers_; }
  StageTimers& timers() { return timers_; }
  const io::CaseConfig& config() const { return config_; }
  double next_time_step();

 private:
  void move_bodies(ParticleState<D>& s);
  void sum_body_loads(const ParticleState<D>& s);

  io::CaseConfig config_;
  std::unique_ptr<FluidModel<D>> model_;
  std::unique_ptr<RigidBodies> bodies_;
  ParticleState<D> state_;
  std::vector<Vec3> point_force_;
  std::vector<std::unique_ptr<ParticleStage<D>>> stages_;
  StageTimers timers_;
  std::vector<std::size_t> slots_;
  std::vector<std::uint32_t> order_;
};

}  // namespace sluice
