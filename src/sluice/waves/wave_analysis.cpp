#include "sluice/waves/wave_analysis.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <numbers>

namespace sluice::waves {

std::complex<double> harmonic(const std::vector<double>& times, const std::vector<double>& values,
                              double omega) {
  // Normal equations of the three-term fit, small and well conditioned over whole periods.
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Vector3d right = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < times.size(); ++i) {
    const Eigen::Vector3d row(std::cos(omega * times[i]), std::sin(omega * times[i]), 1);
    normal += row * row.transpose();
    right += row * values[i];
  }
  const Eigen::Vector3d fit = normal.ldlt().solve(right);
  return {fit[0], fit[1]};
}

IncidentAndReflected incident_and_reflected(std::complex<double> z1, double x1,
                                            std::complex<double> z2, double x2, double k) {
  using std::exp;
  const std::complex<double> i(0, 1);
  // z1 = I e^{ik x1} + R e^{-ik x1}, z2 likewise; the determinant is -2i sin(k (x2 - x1)).
  const std::complex<double> det = exp(i * k * (x1 - x2)) - exp(i * k * (x2 - x1));
  const std::complex<double> incident = (z1 * exp(-i * k * x2) - z2 * exp(-i * k * x1)) / det;
  const std::complex<double> reflected = (z2 * exp(i * k * x1) - z1 * exp(i * k * x2)) / det;
  return {std::abs(incident), std::abs(reflected)};
}

double significant_height(const std::vector<double>& values) {
  double mean = 0;
  for (double v : values) mean += v;
  mean /= static_cast<double>(values.size());
  double m0 = 0;
  for (double v : values) m0 += (v - mean) * (v - mean);
  return 4 * std::sqrt(m0 / static_cast<double>(values.size()));
}

double peak_period(const std::vector<double>& values, double dt, int bands_averaged,
                   double max_frequency) {
  const std::size_t n = values.size();
  const double length = static_cast<double>(n) * dt;
  double mean = 0;
  for (double v : values) mean += v;
  mean /= static_cast<double>(n);
  std::vector<double> power;
  for (int j = 1; j / length <= max_frequency; ++j) {
    std::complex<double> sum = 0;
    const double w = 2 * std::numbers::pi * j / static_cast<double>(n);
    for (std::size_t s = 0; s < n; ++s)
      sum += (values[s] - mean) * std::polar(1.0, -w * static_cast<double>(s));
    power.push_back(std::norm(sum));
  }
  double best = -1, best_frequency = 0;
  for (std::size_t b = 0; b + bands_averaged <= power.size(); ++b) {
    double band = 0, moment = 0;
    for (int m = 0; m < bands_averaged; ++m) {
      band += power[b + m];
      moment += power[b + m] * static_cast<double>(b + m + 1) / length;
    }
    if (band > best) {
      best = band;
      best_frequency = moment / band;
    }
  }
  return 1 / best_frequency;
}

}  // namespace sluice::waves
