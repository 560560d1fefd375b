// The JONSWAP spectrum (Hasselmann et al. 1973) and a sea drawn from it: components of
// deterministic amplitude and random phase (the "random phase" method), repeatable from a seed.
#pragma once

#include <cstdint>
#include <vector>

namespace sluice::waves {

struct JonswapSea {
  double significant_height = 0;  // H_m0 = 4 sqrt(m0) [m]
  double peak_period = 0;         // T_p = 1 / f_p [s]
  double peak_enhancement = 3.3;  // gamma
  double min_frequency = 0;       // [Hz]; the components span [min, max]
  double max_frequency = 0;
  int components = 256;
  std::uint64_t seed = 1;
};

// The spectrum's shape at frequency f [Hz], without its scale (alpha g^2 (2 pi)^-4 = 1):
// f^-5 exp(-1.25 (f_p / f)^4) gamma^r, r = exp(-(f - f_p)^2 / (2 sigma^2 f_p^2)), sigma 0.07 at
// and below the peak, 0.09 above it.
double jonswap_shape(double f, double peak_frequency, double peak_enhancement);

// One component of a sea's surface elevation, amplitude * cos(omega t + phase) at the paddle.
struct WaveComponent {
  double amplitude = 0;  // [m]
  double omega = 0;      // [1/s]
  double phase = 0;      // [rad]
};

// `sea.components` components at the midpoints of equal bands of [min, max] frequency, each of
// amplitude sqrt(2 S(f) df), the spectrum scaled so that the components' 4 sqrt(m0) is H_m0
// exactly, and phases uniform in [0, 2 pi) drawn from a 64-bit Mersenne twister seeded with
// `sea.seed` (the same sea on every machine). The sea repeats after 1 / df.
std::vector<WaveComponent> jonswap_components(const JonswapSea& sea);

}  // namespace sluice::waves
