// The boundary treatments WCSPH can use, by name (`model.boundary`): what they read, and the
// registry. Only Adami et al.'s extrapolated wall particles so far.
#pragma once

#include <string>
#include <vector>

#include "sluice/fluid/boundary_registry.hpp"
#include "sluice/fluid/particle_state.hpp"
#include "sluice/fluid/wcsph/adami_walls.hpp"
#include "sluice/fluid/wcsph/packed_particles.hpp"
#include "sluice/fluid/wcsph/tait.hpp"

namespace sluice {

// What a WCSPH boundary treatment reads and sets.
template <int D, class Kernel>
struct WcsphBoundaryContext {
  ParticleState<D>& state;
  const PackedParticles& packed;  // the fluid, packed for the pair loops
  const Kernel& kernel;
  const TaitEquation& eos;
  std::vector<Vec<D>>& wall_velocity;  // the velocity the viscous terms see at each boundary
};

template <int D, class Kernel>
class AdamiWallTreatment final : public BoundaryTreatment<WcsphBoundaryContext<D, Kernel>> {
 public:
  void update(WcsphBoundaryContext<D, Kernel>& c) override {
    update_adami_walls(c.state, c.packed, c.kernel, c.eos, c.wall_velocity);
  }
};

template <int D, class Kernel>
BoundaryRegistry<WcsphBoundaryContext<D, Kernel>> wcsph_boundaries() {
  BoundaryRegistry<WcsphBoundaryContext<D, Kernel>> registry;
  registry.add("adami", [] { return std::make_unique<AdamiWallTreatment<D, Kernel>>(); });
  return registry;
}

}  // namespace sluice
