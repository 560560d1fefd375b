// Wendland C2 kernel (Wendland 1995), support 2h, in D = 2 or 3 dimensions.
#pragma once

#include <algorithm>
#include <numbers>

#include "sluice/core/host_device.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

template <int D>
struct WendlandC2 {
  static constexpr const char* kName = "wendland";
  // Smallest h/dx (in steps of 0.1) from which the SPH gradient of a linear field on a regular
  // lattice is exact within 1 % in 2D and 3D (tests/unit/kernels); at 1.3 the error is 2-3 %.
  static constexpr double kDefaultHOverDx = 1.5;

  explicit WendlandC2(Real h)
      : h(h),
        inverse_h(1 / h),
        norm(D == 2 ? 7.0 / (4.0 * std::numbers::pi * h * h)
                    : 21.0 / (16.0 * std::numbers::pi * h * h * h)) {}

  SLUICE_HOST_DEVICE Real support() const { return 2 * h; }

  SLUICE_HOST_DEVICE Real value(Real r) const {
    const Real q = r * inverse_h;
    if (q >= 2) return 0;
    const Real t = 1 - 0.5 * q;
    const Real t2 = t * t;
    return norm * t2 * t2 * (2 * q + 1);
  }

  // (1/r) dW/dr, so that grad W(r_ij) = r_ij * gradient_factor(|r_ij|). Finite at r = 0.
  SLUICE_HOST_DEVICE Real gradient_factor(Real r) const {
    const Real q = r * inverse_h;
    if (q >= 2) return 0;
    const Real t = 1 - 0.5 * q;
    return -5 * norm * t * t * t * inverse_h * inverse_h;
  }

  // Single-precision forms without branches (zero beyond the support), for SIMD pair loops.
  SLUICE_HOST_DEVICE float value_branchless(float r) const {
    const float q = r * static_cast<float>(inverse_h);
    const float t = std::max(0.0f, 1.0f - 0.5f * q);
    return static_cast<float>(norm) * t * t * t * t * (2.0f * q + 1.0f);
  }
  SLUICE_HOST_DEVICE float gradient_factor_branchless(float r) const {
    const float t = std::max(0.0f, 1.0f - 0.5f * r * static_cast<float>(inverse_h));
    return static_cast<float>(-5 * norm * inverse_h * inverse_h) * t * t * t;
  }

  Real h;
  Real inverse_h;
  Real norm;
};

}  // namespace sluice
