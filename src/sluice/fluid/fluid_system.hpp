// The interface of a fluid model, whatever its discretisation (particles, a grid): its stages,
// the next stable step and its checkpoint. The rest it offers through three faces, each to
// the part of the engine that needs it: the exchange with the bodies to the coupling scheme
// (coupling/fluid_exchange.hpp), its fields and probes to the output
// (fluid_observation.hpp), its check and last good state to the divergence guard
// (fluid_guard.hpp). The engine (sim/) runs the step as a list of stages; the coupler
// (coupling/) decides when bodies and fluid exchange.
#pragma once

#include <stdexcept>
#include <string>

#include "sluice/core/stage.hpp"
#include "sluice/core/state_archive.hpp"
#include "sluice/core/time_step.hpp"
#include "sluice/coupling/fluid_exchange.hpp"
#include "sluice/fluid/fluid_guard.hpp"
#include "sluice/fluid/fluid_observation.hpp"

namespace sluice {

class FluidSystem {
 public:
  virtual ~FluidSystem() = default;

  // One line with the model's resolved parameters, for `sluice check` and the run header.
  virtual std::string describe() const = 0;
  // The model's stages, in order: `before_bodies` run ahead of the bodies' advance (e.g.
  // moving the particles), `after_bodies` after it (neighbours, forces, integration).
  virtual void append_stages(StageList& before_bodies, StageList& after_bodies) = 0;
  // The stable step for the next step, from the state after the last one, and what limits it.
  virtual TimeStep next_time_step() const = 0;
  // The reach of the model's interactions (a particle model's support): walls are this thick,
  // and a body this far outside the domain has left it.
  virtual double interaction_radius() const = 0;
  // How the fluid is split over the run's ranks, for the run's first line; empty on one rank.
  virtual std::string decomposition() const { return {}; }
  // Checkpoints: writes, or reads back, everything the model carries from one step to the next
  // (core/state_archive.hpp); the model is one built from the same case.
  virtual void archive_state(StateArchive& a) = 0;
  // Resuming a checkpoint written on `written_ranks` ranks, not this run's number (collective):
  // the archive_state reads between the two are the writing ranks' pieces, which the model
  // then splits anew over this run's ranks. Only a model that splits can.
  virtual void begin_gathering(int written_ranks) {
    throw std::logic_error(std::to_string(written_ranks) +
                           " ranks' checkpoint: this model runs on one rank alone");
  }
  virtual void end_gathering() {}

  virtual FluidExchange& exchange() = 0;
  virtual const FluidObservation& observation() const = 0;
  virtual FluidGuard& guard() = 0;
};

}  // namespace sluice
