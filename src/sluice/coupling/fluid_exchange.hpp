// What the coupler exchanges with a fluid, whatever its discretisation: the bodies' motion in,
// the fluid's force and moment on each body out.
#pragma once

#include <vector>

#include "sluice/coupling/body_motion.hpp"

namespace sluice {

class FluidExchange {
 public:
  virtual ~FluidExchange() = default;
  // The bodies have moved: the fluid places its boundary on them.
  virtual void receive_body_motion(const std::vector<BodyKinematics>& motion) = 0;
  // The fluid's force and moment (about the centre of mass) on each body, from its last force
  // evaluation.
  virtual std::vector<Wrench> body_loads(const std::vector<BodyKinematics>& motion) const = 0;
};

}  // namespace sluice
