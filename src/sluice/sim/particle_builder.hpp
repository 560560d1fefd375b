// Turns a validated case into particles: fluid blocks on a lattice with hydrostatic pressure,
// walls as layers of boundary particles thick enough to fill a fluid particle's support.
#pragma once

#include "sluice/fluid/particle_state.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/sim/rigid_bodies.hpp"

namespace sluice {

// Builds the state's particles, sorted by cell: fluid (none inside walls or bodies), walls, and
// the bodies' points. Throws InputError when the case has fluid blocks but no fluid particle
// remains (blocks too small, or entirely inside walls or bodies).
template <int D>
ParticleState<D> build_state(const io::CaseConfig& config, Real interaction_radius,
                             const RigidBodies& bodies);

// Number of boundary-particle layers needed behind a wall for a given interaction radius.
inline int wall_layers(Real interaction_radius, Real dx) {
  return static_cast<int>(std::ceil(interaction_radius / dx - 1e-9));
}

}  // namespace sluice
