#include "sluice/waves/linear_waves.hpp"

#include <cmath>
#include <numbers>

namespace sluice::waves {

double wavenumber(double omega, double depth, double gravity) {
  // Newton on f(x) = x tanh x - w, x = k h, w = omega^2 h / g, from Eckart's (1951) estimate
  // x = w / sqrt(tanh w), within 5 % everywhere; f is convex and increasing in x, so the
  // iterates approach the root from above after the first step.
  const double w = omega * omega * depth / gravity;
  double x = w / std::sqrt(std::tanh(w));
  for (int iteration = 0; iteration < 50; ++iteration) {
    const double t = std::tanh(x);
    const double step = (x * t - w) / (t + x * (1 - t * t));
    x -= step;
    if (std::abs(step) <= 1e-15 * x) break;
  }
  return x / depth;
}

double angular_frequency(double k, double depth, double gravity) {
  return std::sqrt(gravity * k * std::tanh(k * depth));
}

double breaking_height(double k, double depth) {
  return 0.142 * std::tanh(k * depth) * 2 * std::numbers::pi / k;
}

double stokes_second_harmonic(double amplitude, double k, double depth) {
  const double kh = k * depth, s = std::sinh(kh);
  return k * amplitude * amplitude / 4 * std::cosh(kh) * (2 + std::cosh(2 * kh)) / (s * s * s);
}

}  // namespace sluice::waves
