// Builds the constraint-fluid model for a case (registered as `constraint`).
#pragma once

#include <memory>

#include "sluice/coupling/body_geometry.hpp"
#include "sluice/fluid/fluid_system.hpp"
#include "sluice/io/case_config.hpp"

namespace sluice {

template <int D>
std::unique_ptr<FluidSystem> make_constraint(const io::CaseConfig& config,
                                             const BodyGeometry& bodies);

}  // namespace sluice
