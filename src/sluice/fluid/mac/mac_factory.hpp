// Builds the grid model of a case.
#pragma once

#include "sluice/fluid/model_entry.hpp"

namespace sluice {

// The model's registry entry (fluid/model_entry.hpp): its factory, its case hook, its size and
// its devices.
template <int D>
ModelEntry mac_entry();

}  // namespace sluice
