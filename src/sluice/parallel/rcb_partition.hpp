// Recursive coordinate bisection over the ranks, by Zoltan (Sandia's partitioning library,
// Debian's libtrilinos-zoltan-dev; Berger & Bokhari 1987): the second partitioner beside the
// slabs. It cuts the points' region in two along its longest axis at the weighted median, and
// each half again, until there is one box a rank; where several ranks share a slab's work it
// gives bricks with less surface, so fewer ghosts, than as many slabs.
#pragma once

#include <span>
#include <vector>

#include "sluice/parallel/communicator.hpp"
#include "sluice/parallel/decomposition.hpp"

namespace sluice {

// Whether this build has Zoltan (SLUICE_WITH_ZOLTAN).
bool rcb_offered();

// Collective: one box a rank, tiling space, with equal shares of the work of the points every
// rank passes (its own: `dimension` coordinates a point, one after another, and a weight a
// point). The same points on the same ranks give the same boxes.
Decomposition rcb_boxes(const Communicator& ranks, int dimension, std::span<const double> points,
                        std::span<const double> work);

}  // namespace sluice
