// Builds the WCSPH model of a case, with the kernel its parameters name.
#pragma once

#include "sluice/fluid/model_entry.hpp"

namespace sluice {

// The model's registry entry (fluid/model_entry.hpp): its factory, its case hook, its size and
// its devices.
template <int D>
ModelEntry wcsph_entry();

}  // namespace sluice
