#include "sluice/waves/paddle_signal.hpp"

#include <cmath>
#include <numbers>

#include "sluice/waves/linear_waves.hpp"
#include "sluice/waves/paddle_transfer.hpp"

namespace sluice::waves {

namespace {

// The ramp's value and its rate at `time`.
struct Ramp {
  double value = 1, rate = 0;
};

Ramp ramp_at(double time, double ramp_time) {
  if (time >= ramp_time) return {};
  if (time <= 0) return {0, 0};
  const double a = std::numbers::pi / ramp_time;
  return {(1 - std::cos(a * time)) / 2, a * std::sin(a * time) / 2};
}

}  // namespace

double PaddleSignal::displacement(double time) const {
  double x = 0;
  for (const auto& p : parts) x += p.amplitude * std::sin(p.omega * time + p.phase);
  return ramp_at(time, ramp_time).value * x;
}

double PaddleSignal::velocity(double time) const {
  double x = 0, v = 0;
  for (const auto& p : parts) {
    x += p.amplitude * std::sin(p.omega * time + p.phase);
    v += p.amplitude * p.omega * std::cos(p.omega * time + p.phase);
  }
  const Ramp r = ramp_at(time, ramp_time);
  return r.value * v + r.rate * x;
}

double PaddleSignal::elevation(double time) const {
  double eta = 0;
  for (const auto& p : surface) eta += p.amplitude * std::cos(p.omega * time + p.phase);
  return ramp_at(time, ramp_time).value * eta;
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
    if (second_order) {
      signal.parts.push_back(
          {madsen_second_harmonic(2 * w.amplitude, k, depth), 2 * w.omega, 2 * w.phase});
    }
  }
  return signal;
}

}  // namespace sluice::waves
