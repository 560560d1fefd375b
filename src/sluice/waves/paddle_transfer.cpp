#include "sluice/waves/paddle_transfer.hpp"

#include <algorithm>
#include <cmath>

namespace sluice::waves {

double height_over_stroke(double k, double depth, double hinge_depth) {
  const double kh = k * depth;
  // integral_{-h}^{0} f(z) k cosh k(h + z) dz in closed form: sinh kh for a piston, less
  // (cosh kh - cosh k(h - d)) / (k d) for a flap hinged at d < h (the part below the hinge
  // still), or (cosh kh - 1) / (k d) for one hinged at or below the bed.
  double moved = std::sinh(kh);
  if (std::isfinite(hinge_depth)) {
    const double still_below = std::max(depth - hinge_depth, 0.0);
    moved -= (std::cosh(kh) - std::cosh(k * still_below)) / (k * hinge_depth);
  }
  return 4 * std::sinh(kh) / (std::sinh(2 * kh) + 2 * kh) * moved;
}

double madsen_second_harmonic(double height, double k, double depth) {
  const double kh = k * depth, s = std::sinh(kh);
  return height * height / (32 * depth) *
         (3 * std::cosh(kh) / (s * s * s) - 2 / height_over_stroke(k, depth, kPistonHinge));
}

}  // namespace sluice::waves
