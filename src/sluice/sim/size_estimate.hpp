// How large a case is before anything is built: particles (or grid cells) counted from the
// geometry, and the memory they need. A spacing typed a hundred times too small would otherwise
// allocate for minutes before failing; the estimate refuses it at once.
#pragma once

#include <string>

#include "sluice/io/case_config.hpp"

namespace sluice {

struct SizeEstimate {
  std::string element_name;  // "particles" or "cells"
  double elements = 0;       // an upper bound: fluid blocks, wall layers, bodies' volumes
  double bytes = 0;          // elements times the model's measured bytes per element
};

// Counts without allocating (a double: a bad spacing may give more than 2^64).
SizeEstimate estimate_size(const io::CaseConfig& config);

// The machine's physical memory in bytes (0 when it cannot be read).
double machine_memory_bytes();

// "15.5 GB": bytes in the largest unit that keeps them above 1.
std::string readable_bytes(double bytes);

// Throws InputError at the case's `spacing` when the estimate exceeds `available` bytes.
void refuse_if_it_cannot_fit(const io::CaseConfig& config, const SizeEstimate& estimate,
                             double available);

}  // namespace sluice
