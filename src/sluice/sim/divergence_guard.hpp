// Stops a run that has gone wrong: a body whose state is not finite or whose centre of mass
// left the domain, or whatever the fluid finds wrong with itself (a particle with a non-finite
// state, or out of the domain). The fluid keeps its last good state, so the frame written on
// the way out shows the flow just before it broke.
#pragma once

#include <optional>
#include <string>

#include "sluice/fluid/fluid_guard.hpp"
#include "sluice/geometry/axis_box.hpp"
#include "sluice/sim/rigid_bodies.hpp"

namespace sluice {

class DivergenceGuard {
 public:
  // A body whose centre lies outside `escape_box` has left the domain.
  DivergenceGuard(const AxisBox& escape_box, int dimension)
      : escape_box_(escape_box), dimension_(dimension) {}

  // The problem after the step that `clock` counts, or nothing when all is sound.
  std::optional<std::string> check(const StepClock& clock, const FluidGuard& fluid,
                                   const RigidBodies& bodies) const;

 private:
  AxisBox escape_box_;
  int dimension_;
};

}  // namespace sluice
