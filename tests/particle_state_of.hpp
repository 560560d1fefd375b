// A test's look at a particle model's particles. The simulation speaks to its fluid through
// FluidSystem alone, which a grid model implements too; a test that knows its model is a
// particle model looks inside it here.
#pragma once

#include "sluice/fluid/particle_fluid.hpp"
#include "sluice/sim/simulation.hpp"

namespace sluice::testing {

template <int D>
const ParticleState<D>& particle_state(const Simulation<D>& sim) {
  return dynamic_cast<const ParticleFluid<D>&>(sim.fluid()).state();
}

}  // namespace sluice::testing
