// The bodies of a run in islands: bodies that can touch over a coming step (a pair in reach)
// or are joined belong to one island, and no force of the rigid system crosses between
// islands, so that each island can be advanced by a different process of a split run.
// Fixed bodies (walls, prescribed bodies) join no island: nothing moves them, and a wall that
// every body rests on would otherwise tie them all into one.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace sluice {

using IslandPair = std::pair<std::size_t, std::size_t>;

// Each body's island, numbered 0, 1, ... in the order of each island's lowest body; a fixed
// body's is -1. `pairs` and `links` (joints; an end that is not a body, the world, is any
// index >= fixed.size()) tie their two bodies.
std::vector<int> body_islands(const std::vector<bool>& fixed, const std::vector<IslandPair>& pairs,
                              const std::vector<IslandPair>& links);

// Which of `ranks` processes advances each island: the heaviest island first, each to the
// least loaded process so far, the lower rank where two are equal (Graham's longest
// processing time first). `work[i]` is island i's. The same on every process.
std::vector<int> island_ranks(const std::vector<double>& work, int ranks);

}  // namespace sluice
