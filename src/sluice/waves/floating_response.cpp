#include "sluice/waves/floating_response.hpp"

#include <cmath>

namespace sluice::waves {

double box_heave_response(double k, double omega, double depth, double gravity, double beam,
                          double draft, double added_mass_depth) {
  const double half = 0.5 * k * beam;
  const double over_beam = half > 0 ? std::sin(half) / half : 1.0;
  const double force = std::cosh(k * (depth - draft)) / std::cosh(k * depth) * over_beam;
  const double w = omega * omega / gravity;
  return force / (1 - w * draft / (1 - w * added_mass_depth));
}

}  // namespace sluice::waves
