#include "sluice/waves/paddle_signal.hpp"

#include <cmath>
#include <complex>

#include "sluice/core/smooth_ramp.hpp"
#include "sluice/waves/linear_waves.hpp"
#include "sluice/waves/paddle_transfer.hpp"
#include "sluice/waves/second_order_wavemaker.hpp"

namespace sluice::waves {

double PaddleSignal::displacement(double time) const {
  double x = 0;
  for (const auto& p : parts) x += p.amplitude * std::sin(p.omega * time + p.phase);
  return smooth_ramp(time, ramp_time).share * x;
}

double PaddleSignal::velocity(double time) const {
  double x = 0, v = 0;
  for (const auto& p : parts) {
    x += p.amplitude * std::sin(p.omega * time + p.phase);
    v += p.amplitude * p.omega * std::cos(p.omega * time + p.phase);
  }
  const SmoothRamp r = smooth_ramp(time, ramp_time);
  return r.share * v + r.rate * x;
}

double PaddleSignal::elevation(double time) const {
  double eta = 0;
  for (const auto& p : surface) eta += p.amplitude * std::cos(p.omega * time + p.phase);
  return smooth_ramp(time, ramp_time).share * eta;
}

PaddleSignal paddle_signal(const std::vector<WaveComponent>& waves, double depth,
                           double hinge_depth, double gravity, bool second_order,
                           double ramp_time) {
  PaddleSignal signal;
  signal.ramp_time = ramp_time;
  for (const auto& w : waves) {
    const double k = wavenumber(w.omega, depth, gravity);
    signal.parts.push_back(
        {w.amplitude / height_over_stroke(k, depth, hinge_depth), w.omega, w.phase});
    signal.surface.push_back({w.amplitude, w.omega, w.phase});
    if (waves.size() == 1) {
      signal.surface.push_back(
          {stokes_second_harmonic(w.amplitude, k, depth), 2 * w.omega, 2 * w.phase});
    }
    if (second_order && std::isfinite(hinge_depth)) {
      const std::complex<double> f = schaffer_second_order(w.omega, depth, hinge_depth, gravity);
      signal.parts.push_back(
          {w.amplitude * w.amplitude * std::abs(f), 2 * w.omega, 2 * w.phase + std::arg(f)});
    } else if (second_order) {
      signal.parts.push_back(
          {madsen_second_harmonic(2 * w.amplitude, k, depth), 2 * w.omega, 2 * w.phase});
    }
  }
  return signal;
}

}  // namespace sluice::waves
