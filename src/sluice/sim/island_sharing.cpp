#include "sluice/sim/island_sharing.hpp"

#include <algorithm>
#include <cstdint>
#include <string>

#include "sluice/core/state_archive.hpp"
#include "sluice/rigid/body_islands.hpp"

namespace sluice {

std::vector<bool> IslandSharing::bodies_here(const std::vector<SystemBody>& bodies,
                                             const std::vector<Joint>& joints,
                                             BodyInteraction* interaction, double dt) {
  const std::size_t n = bodies.size();
  std::vector<bool> fixed(n);
  for (std::size_t b = 0; b < n; ++b) fixed[b] = bodies[b].fixed;
  const std::vector<IslandPair> pairs =
      interaction ? interaction->pairs_in_reach(bodies, dt) : std::vector<IslandPair>{};
  std::vector<IslandPair> links;
  for (const Joint& joint : joints) links.emplace_back(joint.a, joint.b);
  const std::vector<int> island = body_islands(fixed, pairs, links);
  // An island's work: its bodies, and its pairs in reach (each a narrow phase at every
  // sub-step).
  islands_ = 0;
  for (const int i : island) islands_ = std::max(islands_, i + 1);
  std::vector<double> work(static_cast<std::size_t>(islands_), 0.0);
  for (const int i : island) {
    if (i >= 0) work[static_cast<std::size_t>(i)] += 1;
  }
  for (const IslandPair& p : pairs) {
    const int i = island[fixed[p.first] ? p.second : p.first];
    if (i >= 0) work[static_cast<std::size_t>(i)] += 1;
  }
  const std::vector<int> rank = island_ranks(work, ranks_.size());
  here_.assign(n, false);
  advanced_here_ = 0;
  for (std::size_t b = 0; b < n; ++b) {
    if (island[b] >= 0 && rank[static_cast<std::size_t>(island[b])] == ranks_.rank()) {
      here_[b] = true;
      ++advanced_here_;
    }
  }
  return here_;
}

void IslandSharing::gather(std::vector<SystemBody>& bodies, std::vector<Vec3>& interaction_force,
                           std::vector<Vec3>& interaction_torque, BodyInteraction* interaction) {
  const std::size_t n = bodies.size();
  StateArchive out;
  std::vector<std::uint32_t> mine;
  for (std::size_t b = 0; b < n; ++b) {
    if (here_[b]) mine.push_back(static_cast<std::uint32_t>(b));
  }
  out(mine);
  for (const std::uint32_t b : mine)
    out(bodies[b].state, interaction_force[b], interaction_torque[b]);
  for (std::size_t b = 0; b < n; ++b) {  // a fixed body's contacts lie on every rank
    if (bodies[b].fixed) out(interaction_force[b], interaction_torque[b]);
  }
  if (interaction) interaction->write_share(out);

  const std::vector<std::string> parts = ranks_.gather_all(out.bytes());
  std::vector<StateArchive> readers;
  readers.reserve(parts.size());
  for (const std::string& part : parts) readers.emplace_back(part);
  for (std::size_t b = 0; b < n; ++b) {
    if (!bodies[b].fixed) continue;
    interaction_force[b] = interaction_torque[b] = Vec3::Zero();
  }
  for (StateArchive& in : readers) {
    std::vector<std::uint32_t> theirs;
    in(theirs);
    for (const std::uint32_t b : theirs) {
      if (b >= n) throw StateArchiveError("a rank's bodies: an index past the last body");
      in(bodies[b].state, interaction_force[b], interaction_torque[b]);
    }
    for (std::size_t b = 0; b < n; ++b) {
      if (!bodies[b].fixed) continue;
      Vec3 force, torque;
      in(force, torque);
      interaction_force[b] += force;
      interaction_torque[b] += torque;
    }
  }
  if (interaction) interaction->read_shares(readers);
}

}  // namespace sluice
