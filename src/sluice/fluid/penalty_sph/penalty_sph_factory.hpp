// Builds the penalty-sph model from a case (registered as "penalty-sph" in
// fluid/model_registry.cpp).
#pragma once

#include "sluice/fluid/model_entry.hpp"

namespace sluice {

// The model's registry entry (fluid/model_entry.hpp): its factory, its case hook, its size and
// its devices.
template <int D>
ModelEntry penalty_sph_entry();

}  // namespace sluice
