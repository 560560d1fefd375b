// Cubic spline kernel (Monaghan 1992), support 2h, in D = 2 or 3 dimensions.
#pragma once

#include <algorithm>
#include <numbers>

#include "sluice/core/host_device.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

template <int D>
struct CubicSpline {
  static constexpr const char* kName = "cubic_spline";
  // Smallest h/dx (in steps of 0.1) from which the SPH gradient of a linear field on a regular
  // lattice is exact within 1 % in 2D and 3D (tests/unit/kernels).
  static constexpr double kDefaultHOverDx = 1.6;

  explicit CubicSpline(Real h)
      : h(h),
        inverse_h(1 / h),
        norm(D == 2 ? 10.0 / (7.0 * std::numbers::pi * h * h)
                    : 1.0 / (std::numbers::pi * h * h * h)) {}

  Real support() const { return 2 * h; }

  Real value(Real r) const {
    const Real q = r * inverse_h;
    if (q >= 2) return 0;
    if (q <= 1) return norm * (1 - 1.5 * q * q + 0.75 * q * q * q);
    const Real t = 2 - q;
    return norm * 0.25 * t * t * t;
  }

  // (1/r) dW/dr, so that grad W(r_ij) = r_ij * gradient_factor(|r_ij|). Finite at r = 0.
  Real gradient_factor(Real r) const {
    const Real q = r * inverse_h;
    if (q >= 2) return 0;
    const Real h2 = h * h;
    if (q <= 1) return norm * (-3 + 2.25 * q) / h2;
    const Real t = 2 - q;
    return -0.75 * norm * t * t / (q * h2);
  }

  // Single-precision forms without branches (zero beyond the support), for SIMD pair loops:
  // W = norm (t2^3 / 4 - t1^3) with t2 = max(0, 2 - q), t1 = max(0, 1 - q).
  SLUICE_HOST_DEVICE float value_branchless(float r) const {
    const float q = r * static_cast<float>(inverse_h);
    const float t2 = std::max(0.0f, 2.0f - q), t1 = std::max(0.0f, 1.0f - q);
    return static_cast<float>(norm) * (0.25f * t2 * t2 * t2 - t1 * t1 * t1);
  }
  SLUICE_HOST_DEVICE float gradient_factor_branchless(float r) const {
    const float q = r * static_cast<float>(inverse_h);
    const float t2 = std::max(0.0f, 2.0f - q);
    // A select, not a branch: both sides are computed and the SIMD loop blends them.
    const float shape = q < 1.0f ? -3.0f + 2.25f * q : -0.75f * t2 * t2 / std::max(q, 1.0f);
    return static_cast<float>(norm * inverse_h * inverse_h) * shape;
  }

  Real h;
  Real inverse_h;
  Real norm;
};

}  // namespace sluice
