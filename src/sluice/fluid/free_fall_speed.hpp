// The speed scale of a case: a free fall from the top of the highest fluid block to the floor,
// sqrt(2 g H) (0 without gravity). Models size their sound speed or time step from it.
#pragma once

#include <algorithm>
#include <cmath>

#include "sluice/io/case_config.hpp"

namespace sluice {

inline double free_fall_speed(const io::CaseConfig& config) {
  double top = config.domain.min[2];
  for (const auto& block : config.fluid.blocks) top = std::max(top, block.box.max[2]);
  return std::sqrt(2 * config.gravity.norm() * (top - config.domain.min[2]));
}

}  // namespace sluice
