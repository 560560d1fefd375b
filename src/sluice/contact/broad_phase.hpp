// The broad phase of contact: the pairs of bodies whose bounding boxes come within reach of
// each other. Bodies of ordinary size go into a uniform grid whose cells hold the largest of
// them, so each box touches at most eight cells and the cost follows the number of bodies,
// however many there are; the few large ones (tank sides, planes, anything over four times the
// median size) are tested against every other body directly.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "sluice/geometry/axis_box.hpp"

namespace sluice {

using BodyPair = std::pair<std::uint32_t, std::uint32_t>;

class BroadPhase {
 public:
  // The pairs a < b, in increasing order, whose boxes overlap when each is grown by
  // `margin` / 2, skipping pairs of two fixed bodies. `large[b]`: always treat b as large.
  void find(const std::vector<AxisBox>& boxes, const std::vector<bool>& fixed,
            const std::vector<bool>& large, double margin, std::vector<BodyPair>& pairs);

 private:
  struct Entry {
    std::uint64_t cell;
    std::uint32_t body;
  };
  std::vector<Entry> entries_;
  std::vector<std::uint32_t> large_, ordinary_;
};

}  // namespace sluice
