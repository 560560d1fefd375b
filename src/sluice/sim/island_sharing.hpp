// The bodies of a split run, advanced island by island (rigid/body_islands.hpp): each island
// of bodies that can touch over the coming step, or are joined, goes to one rank, the
// heaviest first to the least loaded; each rank advances its islands' bodies and evaluates
// their contacts (with the walls and fixed bodies too), and after the step every rank gathers
// every body's state, its contacts and the contact solver's figures from the rank that
// advanced it. So every rank holds the whole system between steps (its checkpoint too), and a
// body's motion is the one rank's answer bit for bit: its forces are summed in the same order
// (a fixed body's contact force, output only, sums over the ranks and may differ in its last
// bits).
#pragma once

#include <vector>

#include "sluice/parallel/communicator.hpp"
#include "sluice/rigid/body_sharing.hpp"

namespace sluice {

class IslandSharing final : public BodySharing {
 public:
  explicit IslandSharing(const Communicator& ranks) : ranks_(ranks) {}

  std::vector<bool> bodies_here(const std::vector<SystemBody>& bodies,
                                const std::vector<Joint>& joints, BodyInteraction* interaction,
                                double dt) override;
  void gather(std::vector<SystemBody>& bodies, std::vector<Vec3>& interaction_force,
              std::vector<Vec3>& interaction_torque, BodyInteraction* interaction) override;

  // The islands of the last division, and how many bodies this rank advanced in it.
  int islands() const { return islands_; }
  int bodies_advanced_here() const { return advanced_here_; }

 private:
  Communicator ranks_;
  std::vector<bool> here_;
  int islands_ = 0, advanced_here_ = 0;
};

}  // namespace sluice
