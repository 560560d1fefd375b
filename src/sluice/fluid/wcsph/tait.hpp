// Tait equation of state, p = B ((rho/rho0)^gamma - 1) with B = c0^2 rho0 / gamma
// (Monaghan 1994; Batchelor 1967), optionally clamped from below at zero. Its inverse
// bottoms out at rho0 1e-6^(1/gamma) (139 kg/m^3 for gamma = 7), and so do the model's
// particles' densities (lowest_density).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "sluice/core/host_device.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

struct TaitEquation {
  TaitEquation(Real rest_density, Real sound_speed, Real gamma, bool clamp_negative = false)
      : rho0(rest_density),
        c0(sound_speed),
        gamma(gamma),
        stiffness(sound_speed * sound_speed * rest_density / gamma),
        lowest(clamp_negative ? Real(0) : -std::numeric_limits<Real>::infinity()),
        lowest_density(density(-std::numeric_limits<Real>::infinity())) {}

  SLUICE_HOST_DEVICE Real pressure(Real rho) const {
    const Real ratio = rho / rho0;
    Real p;
    if (gamma == 7) {
      const Real r2 = ratio * ratio;
      p = stiffness * (r2 * r2 * r2 * ratio - 1);
    } else {
      p = stiffness * (std::pow(ratio, gamma) - 1);
    }
    return p > lowest ? p : lowest;
  }

  // Inverse. No density reaches a pressure of -B or below: there 1 + p/B is clamped to 1e-6
  // (rho0 1e-6^(1/gamma): 139 kg/m^3 for gamma = 7), so the density stays finite and positive.
  SLUICE_HOST_DEVICE Real density(Real p) const {
    const Real base = 1 + p / stiffness;
    return rho0 * std::pow(base > Real(1e-6) ? base : Real(1e-6), 1 / gamma);
  }

  Real rho0, c0, gamma, stiffness;
  Real lowest;  // the lowest pressure the equation gives: 0 when negative pressure is clamped
  // The lowest density the inverse gives (above), clamped or not.
  Real lowest_density;
};

}  // namespace sluice
