// Parameters of the grid model (seed 001's third method), read from the case's `model:`
// mapping. Defaults and meanings are documented in docs/case-format.md.
#pragma once

#include <string>

#include "sluice/fluid/mac/mac_grid.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/linear/hypre_session.hpp"

namespace sluice {

struct MacParameters {
  double cell_size = 0;      // the cells' edge [m]; default: the case's spacing
  double cfl = 0.5;          // of a cell the fastest face velocity may cross in a step
  double max_time_step = 0;  // an upper bound on the step [s]; 0 = none
  bool maccormack = true;    // velocity advection: MacCormack, or plain semi-Lagrangian
  // The pressure solver (linear/); "auto": hypre's BoomerAMG from a million cells on (its
  // iterations do not grow with the grid), conjugate gradients with the diagonal below (the
  // faster there; docs/performance.md).
  std::string solver = "auto";
  double tolerance = 1e-8;  // of the pressure solve, |r| / |b|
  int max_iterations = 2000;
  HypreSession* hypre = nullptr;  // the process's, for hypre's solver (linear/sparse_solver.hpp)
  // The particle level set (Enright et al. 2002): marker particles per cell of the interface
  // band, each side; 0 turns the correction off.
  int particles_per_cell = 16;
  // Steps between reinitialisations of the level set: each one moves the surface a little, and
  // every step loses Zalesak's disk 19 % of its area where every 5 keeps it within 3 %.
  int reinitialise_every = 5;
  // The level set shifted after each step to keep its water (volume_correction.hpp). On by
  // default: without it the level set loses the water of every splash (F3: a fifth by 6 s; B5's
  // vehicle: 9 % by 2 s, and an eighth of its drag with it).
  bool volume_correction = true;
};

MacParameters read_mac_parameters(const io::CaseConfig& config);

// The solver that `auto` stands for on a grid of `cells` cells.
std::string mac_pressure_solver(const std::string& solver, std::size_t cells);

// The grid over the case's domain at the parameters' cell size. Throws InputError naming
// model.cell_size when the cells do not fit the domain a whole number of times.
template <int D>
MacGrid<D> mac_grid_of(const io::CaseConfig& config, const MacParameters& p);

}  // namespace sluice
