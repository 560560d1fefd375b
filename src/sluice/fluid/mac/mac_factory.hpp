// Builds the grid model of a case.
#pragma once

#include <memory>

#include "sluice/coupling/body_geometry.hpp"
#include "sluice/fluid/fluid_system.hpp"
#include "sluice/io/case_config.hpp"

namespace sluice {

template <int D>
std::unique_ptr<FluidSystem> make_mac(const io::CaseConfig& config, const BodyGeometry& bodies);

}  // namespace sluice
