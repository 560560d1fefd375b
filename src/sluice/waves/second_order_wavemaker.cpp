#include "sluice/waves/second_order_wavemaker.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "sluice/waves/linear_waves.hpp"

namespace sluice::waves {

namespace {

using Complex = std::complex<double>;

// k_0 = k (real) and the evanescent k_j = -i kappa_j, j = 1 .. modes, of omega^2 = g k tanh kh:
// kappa_j h lies in ((j - 1/2) pi, j pi), where -kappa tan(kappa h) rises from -inf to 0.
std::vector<Complex> wavenumbers(double omega, double depth, double gravity, int modes) {
  std::vector<Complex> k{Complex(wavenumber(omega, depth, gravity), 0)};
  const double w2 = omega * omega;
  for (int j = 1; j <= modes; ++j) {
    double lo = (j - 0.5) * std::numbers::pi / depth, hi = j * std::numbers::pi / depth;
    // Bisection to the last bit: 60 halvings of an interval of pi / (2 h).
    for (int step = 0; step < 60; ++step) {
      const double mid = 0.5 * (lo + hi);
      (w2 + gravity * mid * std::tan(mid * depth) < 0 ? lo : hi) = mid;
    }
    k.emplace_back(0, -0.5 * (lo + hi));
  }
  return k;
}

Complex transfer(double omega, double depth, double hinge_depth, double gravity, int modes) {
  const std::vector<Complex> k = wavenumbers(omega, depth, gravity, modes);
  const double K = wavenumber(2 * omega, depth, gravity);
  const double g = gravity, h = depth, w = omega;
  const bool flap = std::isfinite(hinge_depth);
  const double per_hinge = flap ? 1 / hinge_depth : 0;                     // 1 / D
  const double above_bed = flap ? std::max(depth - hinge_depth, 0.0) : 0;  // d
  const double cosh_Kh = std::cosh(K * h), cosh_Kd = std::cosh(K * above_bed);
  const double sinh_Kd = std::sinh(K * above_bed);
  // First order, eqs. (20), (21): c_j, with c_0 = H / S.
  std::vector<Complex> c(k.size());
  for (std::size_t j = 0; j < k.size(); ++j) {
    const Complex kh = k[j] * h;
    const Complex norm = kh / 2.0 * (kh / (std::sinh(kh) * std::cosh(kh)) + 1.0);
    c[j] = (w * w * h / g - h * per_hinge +
            h * per_hinge * std::cosh(k[j] * above_bed) / std::cosh(kh)) /
           norm;
  }
  // Eq. (41c) and (36b): the flap's terms (zero for a piston).
  const double m1 = per_hinge * g / (4 * w * w) * (cosh_Kd / cosh_Kh - 1);
  Complex single = 0, pairs = 0;
  for (std::size_t j = 0; j < k.size(); ++j) {
    const Complex kj = k[j], kj2 = kj * kj;
    const Complex cosh_ratio = std::cosh(kj * above_bed) * cosh_Kd / (std::cosh(kj * h) * cosh_Kh);
    const Complex sinh_ratio = std::sinh(kj * above_bed) * sinh_Kd / (std::cosh(kj * h) * cosh_Kh);
    const Complex m2 = -g * per_hinge * (K / kj) / (kj2 - K * K) *
                       (2.0 * kj * K * (1.0 - cosh_ratio) -
                        (kj2 + K * K) * (4 * w * w * w * w / (g * g * kj * K) - sinh_ratio));
    single += c[j] * kj2 / (kj2 - K * K) * (-3 * w * w + m2);
    for (std::size_t l = 0; l < k.size(); ++l) {
      const Complex kl = k[l], sum = kj + kl;
      // Eq. (25d), omega_n = omega_m = omega.
      const Complex bound = 2 * w * (w * w - g * g * kj * kl / (w * w)) + w * w * w -
                            g * g / (2 * w) * (kj2 + kl * kl);
      pairs += c[j] * c[l] * sum / (sum * sum - K * K) * bound;
    }
  }
  // Eq. (41b), without the 1/2 of Schäffer's double sum over a spectrum's pairs (n = m).
  const Complex e = K * K * h / (c[0] * c[0] * 8.0 * w * w * w * (1 + m1));
  return e * (-(g / w) * single + pairs);
}

}  // namespace

std::complex<double> schaffer_second_order(double omega, double depth, double hinge_depth,
                                           double gravity, int modes) {
  // Richardson: the sums' error falls as 1 / modes.
  return 2.0 * transfer(omega, depth, hinge_depth, gravity, 2 * modes) -
         transfer(omega, depth, hinge_depth, gravity, modes);
}

}  // namespace sluice::waves
