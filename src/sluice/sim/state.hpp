// Everything one run evolves, passed explicitly to every stage (no global state).
#pragma once

#include <cstdint>
#include <vector>

#include "sluice/core/types.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/neighbor/cell_list.hpp"
#include "sluice/particles/particle_set.hpp"

namespace sluice {

template <int D>
struct SimulationState {
  ParticleSet<D> particles;
  CellList<D> cells;
  Vec<D> gravity = Vec<D>::Zero();
  Real spacing = 0;
  Real rest_density = 1000;
  Real kinematic_viscosity = 0;
  io::AxisBox domain;
  // The domain grown by the wall thickness: a fluid particle outside it has escaped.
  io::AxisBox escape_box;
  double time = 0;
  double dt = 0;
  long step = 0;
  std::size_t fluid_count = 0;
  // Acceleration of each body point over the last step (RigidBodies::points() order): moving
  // walls feel it in their pressure.
  std::vector<Vec3> body_point_acceleration;
};

// A named part of the time step. Stages run in order, each timed on its own.
template <int D>
class Stage {
 public:
  virtual ~Stage() = default;
  virtual const char* name() const = 0;
  virtual void run(SimulationState<D>& state) = 0;
};

// A stage made of a name and a function; enough for most stages.
template <int D, class Fn>
class FunctionStage final : public Stage<D> {
 public:
  FunctionStage(const char* name, Fn fn) : name_(name), fn_(std::move(fn)) {}
  const char* name() const override { return name_; }
  void run(SimulationState<D>& state) override { fn_(state); }

 private:
  const char* name_;
  Fn fn_;
};

template <int D, class Fn>
std::unique_ptr<Stage<D>> make_stage(const char* name, Fn fn) {
  return std::make_unique<FunctionStage<D, Fn>>(name, std::move(fn));
}

}  // namespace sluice
