#include "sluice/fluid/mac/mac_parameters.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "sluice/linear/sparse_solver.hpp"

namespace sluice {

MacParameters read_mac_parameters(const io::CaseConfig& config) {
  io::MapReader model(config.source, config.model, "model", config.model_line);
  model.required<std::string>("name");
  MacParameters p;
  p.cell_size = model.optional_positive("cell_size", config.spacing);
  p.cfl = model.optional_positive("cfl", p.cfl);
  if (p.cfl > 2) model.fail("cfl", fmt::format("must not exceed 2, got {}", p.cfl));
  p.max_time_step = model.optional_positive("max_time_step", 0);
  p.maccormack = model.optional_choice("advection", "maccormack", "advection scheme",
                                       {"maccormack", "semi_lagrangian"}) == "maccormack";
  std::vector<std::string> solvers = sparse_solver_names();
  solvers.insert(solvers.begin(), "auto");
  p.solver = model.optional_choice("solver", p.solver, "pressure solver", solvers);
  p.tolerance = model.optional_positive("tolerance", p.tolerance);
  p.max_iterations = static_cast<int>(model.optional_positive("max_iterations", p.max_iterations));
  p.particles_per_cell =
      static_cast<int>(model.optional_non_negative("particles_per_cell", p.particles_per_cell));
  p.reinitialise_every =
      static_cast<int>(model.optional_positive("reinitialise_every", p.reinitialise_every));
  p.volume_correction = model.optional<bool>("volume_correction", p.volume_correction);
  model.finish();
  return p;
}

std::string mac_pressure_solver(const std::string& solver, std::size_t cells) {
  if (solver != "auto") return solver;
  const std::vector<std::string> names = sparse_solver_names();
  const bool amg = std::find(names.begin(), names.end(), "boomeramg") != names.end();
  return amg && cells >= 1000000 ? "boomeramg" : "cg_diagonal";
}

template <int D>
MacGrid<D> mac_grid_of(const io::CaseConfig& config, const MacParameters& p) {
  MacGrid<D> grid;
  grid.h = p.cell_size;
  const Vec<D> lo = from_3d<D>(config.domain.min), hi = from_3d<D>(config.domain.max);
  grid.origin = lo;
  const char* names = D == 2 ? "xz" : "xyz";
  for (int a = 0; a < D; ++a) {
    const double cells = (hi[a] - lo[a]) / p.cell_size;
    const double whole = std::round(cells);
    if (whole < 1 || std::abs(cells - whole) > 1e-6 * std::max(1.0, cells)) {
      io::MapReader model(config.source, config.model, "model", config.model_line);
      model.fail("cell_size", fmt::format("{} m does not fit the domain: its {} extent of {} m "
                                          "holds {:.4g} cells, not a whole number",
                                          p.cell_size, names[a], hi[a] - lo[a], cells));
    }
    grid.cells[a] = static_cast<int>(whole);
  }
  if (config.periodic) grid.periodic_axis = D == 3 ? config.periodic->axis : 0;
  return grid;
}

template MacGrid<2> mac_grid_of<2>(const io::CaseConfig&, const MacParameters&);
template MacGrid<3> mac_grid_of<3>(const io::CaseConfig&, const MacParameters&);

}  // namespace sluice
