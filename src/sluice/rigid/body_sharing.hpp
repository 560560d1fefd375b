// How the processes of a split run share the advance of the bodies (the penalty method's
// sub-steps): before a step, which bodies this process advances; after it, every body's state
// from the process that advanced it, so that every process again holds the whole system.
// sim/island_sharing.hpp gives each island of bodies (body_islands.hpp) to one process.
#pragma once

#include <vector>

#include "sluice/rigid/body_interaction.hpp"
#include "sluice/rigid/joint.hpp"

namespace sluice {

class BodySharing {
 public:
  virtual ~BodySharing() = default;
  // The bodies this process advances over a coming step of dt (true: here). Every process
  // calls it with the same bodies and gets its part of one division.
  // `interaction` (may be null) says which pairs can come within reach.
  virtual std::vector<bool> bodies_here(const std::vector<SystemBody>& bodies,
                                        const std::vector<Joint>& joints,
                                        BodyInteraction* interaction, double dt) = 0;
  // After the step: each body's state and its interaction force and torque from the process
  // that advanced it (a fixed body's interaction summed over the processes), and the
  // interaction's own state. Collective.
  virtual void gather(std::vector<SystemBody>& bodies, std::vector<Vec3>& interaction_force,
                      std::vector<Vec3>& interaction_torque, BodyInteraction* interaction) = 0;
};

}  // namespace sluice
