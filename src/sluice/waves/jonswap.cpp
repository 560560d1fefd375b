#include "sluice/waves/jonswap.hpp"

#include <cmath>
#include <numbers>
#include <random>

namespace sluice::waves {

double jonswap_shape(double f, double peak_frequency, double peak_enhancement) {
  const double sigma = f <= peak_frequency ? 0.07 : 0.09;
  const double off = (f - peak_frequency) / (sigma * peak_frequency);
  const double r = std::exp(-0.5 * off * off);
  const double ratio = peak_frequency / f;
  return std::pow(f, -5) * std::exp(-1.25 * ratio * ratio * ratio * ratio) *
         std::pow(peak_enhancement, r);
}

std::vector<WaveComponent> jonswap_components(const JonswapSea& sea) {
  const double fp = 1 / sea.peak_period;
  const int n = sea.components;
  const double df = (sea.max_frequency - sea.min_frequency) / n;
  std::vector<WaveComponent> out(n);
  double m0 = 0;
  for (int i = 0; i < n; ++i) {
    const double f = sea.min_frequency + (i + 0.5) * df;
    out[i].omega = 2 * std::numbers::pi * f;
    out[i].amplitude = jonswap_shape(f, fp, sea.peak_enhancement) * df;  // S df, unscaled
    m0 += out[i].amplitude;
  }
  // The phases from the engine's raw 64-bit draws (its sequence is fixed by the standard;
  // a distribution's is not).
  std::mt19937_64 engine(sea.seed);
  const double target_m0 = sea.significant_height * sea.significant_height / 16;
  for (auto& c : out) {
    c.amplitude = std::sqrt(2 * c.amplitude * target_m0 / m0);
    c.phase = 2 * std::numbers::pi * static_cast<double>(engine() >> 11) * 0x1.0p-53;
  }
  return out;
}

}  // namespace sluice::waves
