#include "sluice/fluid/mac/mac_factory.hpp"

#include <cmath>

#include "sluice/fluid/mac/mac_model.hpp"
#include "sluice/geometry/sampling.hpp"

namespace sluice {

namespace {

// The cells of the case's grid: its domain at model.cell_size (the spacing stands in until the
// model's own reader reports a bad cell_size).
double grid_cells(const io::CaseConfig& config) {
  double h = config.spacing;
  if (config.model["cell_size"]) h = config.model["cell_size"].as<double>(h);
  if (!(std::isfinite(h) && h > 0)) h = config.spacing;
  return lattice_points(config.domain.max - config.domain.min, h, config.dimension);
}

template <int D>
std::unique_ptr<FluidSystem> make_mac(const io::CaseConfig& config, const BodyGeometry& bodies,
                                      const ModelServices& services) {
  MacParameters parameters = read_mac_parameters(config);
  parameters.hypre = services.hypre;
  return std::make_unique<MacModel<D>>(parameters, config, bodies);
}

}  // namespace

template <int D>
ModelEntry mac_entry() {
  ModelEntry entry;
  entry.make = make_mac<D>;
  entry.size.bytes_per_element = 400;  // measured: docs/output.md
  entry.size.element_name = "cells";
  entry.size.elements = grid_cells;
  // Its pressure solves the bodies' velocities (Batty et al. 2007), their joints and contacts
  // kept, and in the projection scheme the bodies take them: its own. With held loads a body held
  // by a contact is immobile to the projection and takes no load (docs/architecture.md).
  entry.schemes = {"projection", "held-loads"};
  entry.one_rank_only = "its grid is not split over ranks yet";
  entry.open_boundaries = true;
  entry.periodic = true;
  entry.damping_zones = true;
  return entry;
}

template ModelEntry mac_entry<2>();
template ModelEntry mac_entry<3>();

}  // namespace sluice
