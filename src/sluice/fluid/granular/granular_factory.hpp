// Builds the granular model for a case of dimension D.
#pragma once

#include "sluice/fluid/model_entry.hpp"

namespace sluice {

// The model's registry entry (fluid/model_entry.hpp): its factory, its case hook, its size and
// its devices.
template <int D>
ModelEntry granular_entry();

}  // namespace sluice
