// Parameters of the weakly compressible SPH model, read from the case's `model:` mapping.
// Defaults and meanings are documented in docs/case-format.md.
#pragma once

#include <string>

#include "sluice/fluid/wcsph/wcsph_device_run.hpp"
#include "sluice/io/case_config.hpp"

namespace sluice {

enum class KernelChoice { kWendlandC2, kCubicSpline };

struct WcsphParameters {
  KernelChoice kernel = KernelChoice::kWendlandC2;
  double h_over_dx = 0;                    // h = h_over_dx * spacing; 0 = the kernel's default
  double sound_speed = 0;                  // c0; 0 = speed_factor * max_speed
  double speed_factor = 10;                // c0 = speed_factor * max_speed
  double max_speed = 0;                    // expected largest speed; 0 = sqrt(2 g H) of the fluid
  double gamma = 7;                        // Tait exponent
  double artificial_viscosity = 0.02;      // Monaghan's alpha
  double density_diffusion = 0.1;          // delta of the density-diffusion term
  double cfl = 0.2;                        // acoustic Courant number
  double force_cfl = 0.25;                 // coefficient of sqrt(h / |a|max)
  bool no_slip = true;                     // walls: no-slip (true) or free-slip
  bool clamp_negative_pressure = false;    // the equation of state gives no pressure below 0
  double background_pressure = 0;          // p_b of the transport velocity; 0: none
  std::string boundary = "adami";          // the boundary treatment, by name (wcsph_boundaries)
  WcsphDevice device = WcsphDevice::kCpu;  // where the particles live and the loops run
  bool time_device_stages = false;         // wait for the device at the end of every stage

  double smoothing_length(double dx) const { return h_over_dx * dx; }
};

// Reads model: parameters and resolves the automatic ones from the case.
WcsphParameters read_wcsph_parameters(const io::CaseConfig& config);

}  // namespace sluice
