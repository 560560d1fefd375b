// The models sluice ships, by the names a case gives in `model.name`: the one place that names
// them all (each model's own folder returns its registry entry).
#pragma once

#include "sluice/fluid/model_registry.hpp"

namespace sluice {

// Every model sluice ships, for a case of dimension D.
template <int D>
ModelRegistry shipped_models();
// The same, for a case of `dimension` (2 or 3).
ModelRegistry shipped_models(int dimension);

}  // namespace sluice
