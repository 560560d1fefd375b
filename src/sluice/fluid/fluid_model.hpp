// The interface every fluid model implements. The engine owns the particles, the neighbour
// search and the step loop; a model adds its fields and its stages.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sluice/fluid/particle_state.hpp"
#include "sluice/io/case_config.hpp"

namespace sluice {

template <int D>
class FluidModel {
 public:
  virtual ~FluidModel() = default;

  // Radius within which particles interact; sets the cell size and the wall thickness.
  virtual Real interaction_radius() const = 0;

  // Called once the particles exist (with hydrostatic pressure set): adds the model's
  // fields, sets densities, and evaluates what the first step needs. Neighbours are sorted.
  virtual void initialize(ParticleState<D>& state) = 0;

  // The model's stages, in order, around the engine's neighbour search: `before` runs ahead of
  // it (e.g. moving the particles), `after` after it.
  virtual void append_stages(std::vector<std::unique_ptr<ParticleStage<D>>>& before,
                             std::vector<std::unique_ptr<ParticleStage<D>>>& after) = 0;

  // The stable step for the next step, from the state after the last one.
  virtual double next_time_step(const ParticleState<D>& state) const = 0;

  // The fluid's force on every body point (kind kBody), indexed by its body_point, from the
  // last force evaluation. `force` has one entry per body point, zero on entry.
  virtual void body_point_forces(const ParticleState<D>& state, std::vector<Vec3>& force) const = 0;

  // One line with the model's resolved parameters, for `sluice check` and the run header.
  virtual std::string describe() const = 0;
};

// Creates the model named in the case (model.name), reading and validating its parameters.
template <int D>
std::unique_ptr<FluidModel<D>> make_fluid_model(const io::CaseConfig& config);

}  // namespace sluice
