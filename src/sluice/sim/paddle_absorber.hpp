// Active absorption at a wave paddle: besides its signal, the paddle moves so as to cancel the
// waves that come back to it, instead of reflecting them into the flume again. The water is
// measured a little before the paddle's face at the start of every step, from its own mean
// level; its excess over the elevation the signal makes there is a wave arriving, and the
// paddle adds the velocity that makes a wave of the opposite elevation,
//   U = G (eta_target - (eta - eta_mean)) - X / (10 T),
// G = omega / (H/S) the transfer function read backwards at the wave's (peak) frequency
// (sqrt(g / h) for a piston in shallow water; the linear absorber of Schäffer & Klopman 2000,
// Journal of Waterway, Port, Coastal and Ocean Engineering 126(2), there with a filter over
// frequency, here tuned to one). T is the wave's period. eta_mean, the reading's running mean
// over ten periods (from the first reading on), keeps a steady error of the reading (a particle
// model's gauge reads in quarter spacings; its water settles) from setting the paddle off; the
// leak, over ten periods too, brings the paddle back to its mean position. Each passes under
// 2 % of the wave's frequency. The reading is taken as if at the face: the gap costs a reflection
// of about tan(k gap / 2) (3-4 % at two cells of 0.02 m and kh = 1).
#pragma once

#include "sluice/core/state_archive.hpp"
#include "sluice/fluid/fluid_observation.hpp"
#include "sluice/io/body_config.hpp"
#include "sluice/sim/prescribed_motion.hpp"

namespace sluice {

class PaddleAbsorber {
 public:
  // `paddle` (a box wavemaker with active absorption; kept by reference) in a domain whose
  // floor is at `floor`, its water measured `gap` before its face.
  PaddleAbsorber(const io::BodyConfig& paddle, double floor, double gap);

  // The correction at `time`, on or after the last measure().
  PaddleCorrection at(double time) const;
  // Reads the water before the face at `time` (on every rank alike: the reading is collective)
  // and sets the correction's velocity from then on.
  void measure(double time, const FluidObservation& fluid);

  void archive_state(StateArchive& a) { a(since_, displacement_, velocity_, mean_, read_); }

 private:
  const io::BodyConfig& paddle_;
  double floor_, gap_, leak_time_;
  double since_ = 0;         // the last measure()'s time
  double displacement_ = 0;  // the correction's displacement then [m]
  double velocity_ = 0;      // and its velocity since [m/s]
  double mean_ = 0;          // the reading's running mean [m above the still water line]
  bool read_ = false;        // whether it has read the water yet
};

}  // namespace sluice
