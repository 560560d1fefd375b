// Where a water-height gauge reads the surface: the top of the lowest water on its vertical line.
#pragma once

#include <cstddef>

namespace sluice {

// Given n samples up a gauge's vertical line, from the floor, and whether each is water, the
// index of the last sample of the lowest run of water: the top of the water standing on the bed,
// as a wire gauge reads it and DualSPHysics's GaugeSwl does (from the bottom up, to the first
// drop below its limit). Spray and sheets thrown up above that water do not count. A run of at
// most `bridged` dry samples between water is taken as water (a particle model's kernel sum can
// dip between layers of its particles); -1 where no sample is water.
template <class IsWater>
std::ptrdiff_t top_of_lowest_water(std::size_t n, IsWater is_water, std::size_t bridged = 0) {
  std::size_t k = 0;
  while (k < n && !is_water(k)) ++k;
  if (k == n) return -1;
  std::size_t top = k;
  for (std::size_t dry = 0; ++k < n && dry <= bridged;) {
    if (is_water(k)) {
      top = k;
      dry = 0;
    } else {
      ++dry;
    }
  }
  return static_cast<std::ptrdiff_t>(top);
}

}  // namespace sluice
