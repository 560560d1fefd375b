// A paddle's displacement at the still water line in time: a sum of sines for the waves it
// makes, started from rest over a ramp.
#pragma once

#include <vector>

#include "sluice/waves/jonswap.hpp"

namespace sluice::waves {

// One part of the displacement, amplitude * sin(omega t + phase) [m].
struct StrokeComponent {
  double amplitude = 0;
  double omega = 0;
  double phase = 0;
};

struct PaddleSignal {
  std::vector<StrokeComponent> parts;
  // The sea it makes at the paddle's rest position, each part's elevation amplitude *
  // cos(omega t + phase) [m] (ramped as the displacement is): what active absorption takes
  // from the water it measures there to find the waves coming back.
  std::vector<StrokeComponent> surface;
  // The displacement is multiplied by (1 - cos(pi t / ramp_time)) / 2 until ramp_time, so that
  // the paddle starts at rest (no impulsive start, no drift of its mean position).
  double ramp_time = 0;

  double displacement(double time) const;
  double velocity(double time) const;
  double elevation(double time) const;
};

// What makes the sea `waves` (each component's elevation at the paddle's rest position,
// amplitude * cos(omega t + phase)) on water `depth` deep with the paddle hinged `hinge_depth`
// below the still water line (kPistonHinge: a piston): each component through the transfer
// function at its own frequency, as (amplitude / (H/S)) sin(omega t + phase) (the paddle moves
// forward fastest under a crest). `second_order`: add the second harmonic that cancels the
// spurious free wave to each component (meant for one wave train): Madsen's (1971) for a piston,
// Schäffer's (1996) for a flap (second_order_wavemaker.hpp). The surface of one wave train has the
// Stokes second-order harmonic that the wave carries with it, whatever the paddle's order; a
// sea of several components has their first-order sum.
PaddleSignal paddle_signal(const std::vector<WaveComponent>& waves, double depth,
                           double hinge_depth, double gravity, bool second_order, double ramp_time);

}  // namespace sluice::waves
