// The boundary treatments WCSPH can use, by name (`model.boundary`): what they read, and the
// registry. Only Adami et al.'s extrapolated wall particles so far.
#pragma once

#include <string>
#include <vector>

#include "sluice/exec/policy.hpp"
#include "sluice/fluid/boundary_registry.hpp"
#include "sluice/fluid/wcsph/adami_walls.hpp"
#include "sluice/fluid/wcsph/packed_particles.hpp"
#include "sluice/fluid/wcsph/wcsph_fields.hpp"

namespace sluice {

// What a WCSPH boundary treatment reads and sets (the boundaries' pressure, density and
// wall_velocity).
template <int D, class Kernel>
using WcsphBoundaryContext = WcsphNeighbourhood<D, Kernel>;

template <int D, class Kernel>
class AdamiWallTreatment final : public BoundaryTreatment<WcsphBoundaryContext<D, Kernel>> {
 public:
  void update(WcsphBoundaryContext<D, Kernel>& c) override {
    exec::Default::for_each_balanced(c.f.size, AdamiWall<D, Kernel>{c});
  }
};

template <int D, class Kernel>
BoundaryRegistry<WcsphBoundaryContext<D, Kernel>> wcsph_boundaries() {
  BoundaryRegistry<WcsphBoundaryContext<D, Kernel>> registry;
  registry.add("adami", [] { return std::make_unique<AdamiWallTreatment<D, Kernel>>(); });
  return registry;
}

}  // namespace sluice
