// Builds the constraint-fluid model for a case (registered as `constraint`).
#pragma once

#include "sluice/fluid/model_entry.hpp"

namespace sluice {

// The model's registry entry (fluid/model_entry.hpp): its factory, its case hook, its size and
// its devices.
template <int D>
ModelEntry constraint_entry();

}  // namespace sluice
