// Builds the MPS model from a case (registered as "mps" in fluid/model_registry.cpp).
#pragma once

#include "sluice/fluid/model_entry.hpp"

namespace sluice {

// The model's registry entry (fluid/model_entry.hpp): its factory, its case hook, its size and
// its devices.
template <int D>
ModelEntry mps_entry();

}  // namespace sluice
