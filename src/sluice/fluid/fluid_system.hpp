// The interface of a fluid model, whatever its discretisation (particles, a grid): its stages,
// the next stable step, the exchange with the bodies (coupling/fluid_exchange.hpp), its output
// fields, probe queries, and the check for a run gone wrong. The engine (sim/) runs the step
// as a list of stages; the coupler (coupling/) decides when bodies and fluid exchange.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sluice/core/stage.hpp"
#include "sluice/core/state_archive.hpp"
#include "sluice/core/time_step.hpp"
#include "sluice/coupling/fluid_exchange.hpp"
#include "sluice/fluid/fluid_energy.hpp"
#include "sluice/io/vtk_writer.hpp"

namespace sluice {

// How big the fluid is: its elements (particles or cells) and, of them, the fluid ones.
struct FluidSize {
  const char* element_name = "particles";  // what an element is, in messages
  std::size_t elements = 0;
  std::size_t fluid = 0;
  std::size_t wall = 0;
  std::size_t body = 0;
};

class FluidSystem : public FluidExchange {
 public:
  // One line with the model's resolved parameters, for `sluice check` and the run header.
  virtual std::string describe() const = 0;
  // The model's stages, in order: `before_bodies` run ahead of the bodies' advance (e.g.
  // moving the particles), `after_bodies` after it (neighbours, forces, integration).
  virtual void append_stages(StageList& before_bodies, StageList& after_bodies) = 0;
  // The stable step for the next step, from the state after the last one, and what limits it.
  virtual TimeStep next_time_step() const = 0;

  // Output (docs/output.md): the fluid as points with named arrays; a grid model: its free
  // surface, and its cells with theirs.
  virtual io::FluidFrame frame() const = 0;
  // Probes: Shepard-averaged pressure at a point; height of the water column above the
  // domain's floor on a vertical gauge at (x, y); the furthest fluid along an axis (0 = x,
  // 1 = y).
  virtual double pressure_at(const Vec3& x) const = 0;
  virtual double water_height_at(const Vec3& gauge) const = 0;
  virtual double surge_front(int axis) const = 0;

  // What is wrong with the fluid, if anything (the message names the place).
  virtual std::optional<std::string> check(const StepClock& clock) const = 0;
  // Keeps the present state as the last good one, and its frame.
  virtual void remember_good(double time) = 0;
  virtual io::FluidFrame last_good_frame() const = 0;
  virtual double last_good_time() const = 0;

  virtual FluidSize size() const = 0;
  virtual FluidEnergy energy() const = 0;  // and the fluid's mass
  // The model's own running totals, for the run's statistics (MPS: pressure solves and their
  // iterations); none by default.
  virtual std::vector<std::pair<std::string, double>> counters() const { return {}; }
  // The reach of the model's interactions (a particle model's support): walls are this thick,
  // and a body this far outside the domain has left it.
  virtual double interaction_radius() const = 0;

  // Checkpoints: writes, or reads back, everything the model carries from one step to the next
  // (core/state_archive.hpp); the model is one built from the same case.
  virtual void archive_state(StateArchive& a) = 0;
};

}  // namespace sluice
