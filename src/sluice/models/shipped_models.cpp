#include "sluice/models/shipped_models.hpp"

#include "sluice/fluid/constraint/constraint_factory.hpp"
#include "sluice/fluid/granular/granular_factory.hpp"
#include "sluice/fluid/mac/mac_factory.hpp"
#include "sluice/fluid/mps/mps_factory.hpp"
#include "sluice/fluid/penalty_sph/penalty_sph_factory.hpp"
#include "sluice/fluid/wcsph/wcsph_factory.hpp"

namespace sluice {

template <int D>
ModelRegistry shipped_models() {
  ModelRegistry registry;
  registry.add("wcsph", wcsph_entry<D>());
  registry.add("mps", mps_entry<D>());
  registry.add("penalty-sph", penalty_sph_entry<D>());
  registry.add("granular", granular_entry<D>());
  registry.add("constraint", constraint_entry<D>());
  registry.add("mac", mac_entry<D>());
  return registry;
}

ModelRegistry shipped_models(int dimension) {
  return dimension == 2 ? shipped_models<2>() : shipped_models<3>();
}

template ModelRegistry shipped_models<2>();
template ModelRegistry shipped_models<3>();

}  // namespace sluice
