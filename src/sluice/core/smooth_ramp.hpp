// A smooth start from rest: the share (1 - cos(pi t / T)) / 2 of full strength at time t over
// a ramp of T seconds (0 before the start, 1 from T on; T = 0: at once), with its rate and its
// integral from 0. Bodies, paddles and inlets start so, which spares the fluid the pressure
// wave of an impulsive start.
#pragma once

#include <cmath>
#include <numbers>

namespace sluice {

struct SmoothRamp {
  double share = 1;     // of full strength
  double rate = 0;      // d share / dt
  double integral = 0;  // of the share from 0 to t: the time spent at full strength
};

inline SmoothRamp smooth_ramp(double time, double ramp_time) {
  if (time >= ramp_time) return {1, 0, time - ramp_time / 2};
  if (time <= 0) return {0, 0, 0};
  const double a = std::numbers::pi / ramp_time;
  return {(1 - std::cos(a * time)) / 2, a * std::sin(a * time) / 2,
          (time - std::sin(a * time) / a) / 2};
}

}  // namespace sluice
