// The three kernels of Müller, Charypar & Gross (2003), "Particle-based fluid simulation for
// interactive applications", each with support h (not 2h): poly6 for the density and the
// colour field; spiky for the pressure force (its gradient does not vanish as r -> 0, so close
// particles still push apart); and the viscosity kernel, used only through its Laplacian,
// positive everywhere. The 3D constants are the paper's; the 2D ones follow the same rules:
// poly6 and spiky integrate to one, and the viscosity Laplacian gives the Laplacian of a
// quadratic field exactly in the continuum (tests/unit/kernels/test_muller_kernels.cpp).
#pragma once

#include <numbers>

#include "sluice/core/host_device.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

template <int D>
struct MullerKernels {
  explicit MullerKernels(Real h) : h(h), h2(h * h) {
    constexpr double pi = std::numbers::pi;
    if constexpr (D == 2) {
      poly6_norm = 4 / (pi * pow_(h, 8));
      spiky_norm = 10 / (pi * pow_(h, 5));
      viscosity_norm = 40 / (pi * pow_(h, 5));
    } else {
      poly6_norm = 315 / (64 * pi * pow_(h, 9));
      spiky_norm = 15 / (pi * pow_(h, 6));
      viscosity_norm = 45 / (pi * pow_(h, 6));
    }
  }

  SLUICE_HOST_DEVICE Real support() const { return h; }

  // W_poly6 = N (h^2 - r^2)^3.
  SLUICE_HOST_DEVICE Real poly6(Real r) const {
    if (r >= h) return 0;
    const Real t = h2 - r * r;
    return poly6_norm * t * t * t;
  }
  // (1/r) dW_poly6/dr: grad W(r_ij) = r_ij * poly6_gradient_factor(|r_ij|).
  SLUICE_HOST_DEVICE Real poly6_gradient_factor(Real r) const {
    if (r >= h) return 0;
    const Real t = h2 - r * r;
    return -6 * poly6_norm * t * t;
  }
  // lap W_poly6 = -6 N (h^2 - r^2) (3 h^2 - 7 r^2) in 3D, -12 N (h^2 - r^2) (h^2 - 3 r^2) in 2D.
  SLUICE_HOST_DEVICE Real poly6_laplacian(Real r) const {
    if (r >= h) return 0;
    const Real r2 = r * r;
    if constexpr (D == 2) return -12 * poly6_norm * (h2 - r2) * (h2 - 3 * r2);
    return -6 * poly6_norm * (h2 - r2) * (3 * h2 - 7 * r2);
  }

  // W_spiky = N (h - r)^3.
  SLUICE_HOST_DEVICE Real spiky(Real r) const {
    if (r >= h) return 0;
    const Real t = h - r;
    return spiky_norm * t * t * t;
  }
  // (1/r) dW_spiky/dr; zero at r = 0, where the direction is undefined.
  SLUICE_HOST_DEVICE Real spiky_gradient_factor(Real r) const {
    if (r >= h || r <= 0) return 0;
    const Real t = h - r;
    return -3 * spiky_norm * t * t / r;
  }

  // lap W_viscosity = N (h - r).
  SLUICE_HOST_DEVICE Real viscosity_laplacian(Real r) const {
    return r >= h ? 0 : viscosity_norm * (h - r);
  }

  Real h, h2;
  Real poly6_norm = 0, spiky_norm = 0, viscosity_norm = 0;

 private:
  static constexpr Real pow_(Real x, int n) {
    Real p = 1;
    for (int k = 0; k < n; ++k) p *= x;
    return p;
  }
};

}  // namespace sluice
