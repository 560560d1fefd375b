// Parameters of the MPS model, read from the case's `model:` mapping. Defaults, meanings and
// sources are documented in docs/case-format.md.
#pragma once

#include <string>

#include "sluice/io/case_config.hpp"
#include "sluice/linear/sparse_solver.hpp"

namespace sluice {

enum class MpsVariant {
  kIncompressible,  // pressure from the pressure Poisson equation
  kExplicit,        // pressure from the number density through an equation of state
};

// Where the walls' and bodies' particles get their pressure.
enum class MpsWallPressure {
  kExtrapolated,  // from the fluid around them (Adami et al. 2012); not symmetric
  kSolved,        // a Poisson row of their own, first layer only (Koshizuka & Oka 1996)
};

struct MpsParameters {
  MpsVariant variant = MpsVariant::kIncompressible;
  double re_over_dx = 2.1;            // C_e: effective radius r_e = C_e l0
  double laplacian_re_over_dx = 0;    // the Laplacian's own C_e; 0 = re_over_dx
  double surface_threshold = 0.97;    // beta: surface when n* < beta n0 ...
  double surface_count_ratio = 0.85;  // ... and fewer than this share of n0's neighbours
  double source_relaxation = 0.01;    // gamma: weight of the density-deviation source
  double compressibility = 4.5e-10;   // alpha in 1/Pa (water's own)
  bool pressure_memory = true;        // false: Ikeda's form, which forgets p^n (comparison)
  bool keep_negative_pressure = false;
  bool gradient_correction = true;  // the corrective matrix in the pressure gradient
  // The number density n* / n0 from which the pressure gradient measures against the
  // neighbourhood's smallest pressure p^ (which keeps particles from clustering); below it,
  // near a free surface, against the particle's own. There the neighbourhood is one-sided,
  // the term (p_i - p^) C^-1 sum r w / r^2 does not average out, and it carried 5-7 % of the
  // water's weight in the top layers of 3D water: a body a few spacings under the surface
  // felt 10.7 % less than its hydrostatic lift (docs/validation.md, B5). 0: p^ everywhere.
  double minimum_density = 0.98;
  MpsWallPressure wall_pressure = MpsWallPressure::kExtrapolated;
  double artificial_viscosity = 0.05;  // explicit variant: nu_a = alpha c0 l0
  double collision_distance = 0.85;    // in l0; 0 turns the collision model off
  double collision_restitution = 0.2;
  double cfl = 0.2;        // Courant number on the particle spacing
  double sound_speed = 0;  // explicit variant's c0; 0 = speed_factor * max_speed
  double speed_factor = 10;
  double max_speed = 0;  // expected largest speed; 0 = sqrt(2 g H)
  std::string solver;    // default: bicgstab_diagonal (extrapolated walls), cg_diagonal (solved)
  // The cap on iterations: at 0.0125 m the 2D dam break's impact on the far wall takes one
  // BiCGSTAB solve past 1000 (236 a solve on average).
  SolverSettings solver_settings{1e-8, 5000};
  // Where the step's loops run: the host's particle set, or the emulated device's copy of it
  // (mps_device_run.hpp), which gives the same answer to the bit.
  bool emulated_device = false;
};

MpsParameters read_mps_parameters(const io::CaseConfig& config);

}  // namespace sluice
