// Parameters of the penalty-sph model (seed 002), read from the case's `model:` mapping.
// Defaults, meanings and sources are documented in docs/case-format.md.
#pragma once

#include <string>
#include <vector>

#include "sluice/geometry/sampling.hpp"
#include "sluice/io/body_config.hpp"
#include "sluice/io/case_config.hpp"

namespace sluice {

// A box of solid particles on a lattice of their own spacing L_b = spacing_ratio * dx (seed
// 002's concrete and granular beds): fixed in place, or free, each particle then a grain (a
// sphere of diameter L_b) among the case's rigid bodies.
struct SolidLayerConfig {
  AxisBox box;
  double spacing_ratio = 1;  // L_b / dx
  double density = 2800;     // of the solid [kg/m^3]: a free grain's mass
  bool free = false;
  ContactMaterial material;  // of a free layer's grains
  std::string key;           // its key path, for messages: "model.solids[0]"
  int line = 0;
};

struct PenaltySphParameters {
  double kernel_particles = 20;         // particles in the support sphere (Kelager 2006): sets h
  double gas_stiffness = 0;             // k in p = k (rho - rho0) [m^2/s^2]; 0 = c0^2
  bool keep_negative_pressure = false;  // false: p >= 0, no tension that clumps the surface
  double speed_factor = 10;             // c0 = speed_factor * max_speed
  double max_speed = 0;                 // expected largest speed; 0 = sqrt(2 g H)
  bool muller_pressure_force = false;   // true: (p_i + p_j)/2, Müller et al.'s half gradient
  double artificial_viscosity = 0.05;   // Monaghan's alpha, on the support h and c0 = sqrt(k)
  double buoyancy = 0;                  // b: the force b (rho - rho0) g
  double surface_tension = 0.0728;      // sigma [N/m] (water at 20 C)
  double surface_threshold = 7.065;     // l [1/m]: tension where the colour gradient exceeds it
  double stiffness = 0;                 // Ks [N/m]; 0 = the energy rule (docs/case-format.md)
  double damping = 0;                   // Kd [N s/m]; 0 = critical for one contact
  double wall_friction = 0;             // mu_w [Pa s] of the no-slip traction; 0 = the fluid's mu
  double time_step = 0;                 // a fixed step [s]; 0 = the stability limits
  double cfl = 0.25;
  std::vector<SolidLayerConfig> solids;
  // Where the step's loops run: the host's particle set, or the emulated device's copy of it
  // (penalty_sph_device_run.hpp), which gives the same answer to the bit. Not with solids.
  bool emulated_device = false;

  // h for the spacing: the radius of a sphere (3D) or disc (2D) holding kernel_particles.
  double smoothing_length(double spacing, int dimension) const;
};

PenaltySphParameters read_penalty_sph_parameters(const io::CaseConfig& config);

// The centres of a solid layer's particles: its box, within the domain, on a lattice of spacing
// L_b. Throws InputError when it holds none.
template <int D>
std::vector<Vec<D>> solid_layer_points(const SolidLayerConfig& layer, const io::CaseConfig& config);

// The grains of the case's free solid layers, as sphere bodies to add to its own (in layer
// order, each layer's grains in lattice order), named LAYER_grainN.
std::vector<io::BodyConfig> free_solid_grains(const io::CaseConfig& config);

}  // namespace sluice
