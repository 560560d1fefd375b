// Progress of a long run: on a terminal one live line (simulated time, steps, throughput,
// ETA) redrawn in place; otherwise a plain line every `plain_interval` seconds of wall time.
#pragma once

#include <chrono>
#include <cstdio>

namespace sluice {

class ProgressReporter {
 public:
  // `start_time`: where the run starts (a resumed run: its checkpoint's time), for the ETA.
  ProgressReporter(double end_time, std::FILE* stream, bool live, double plain_interval = 10.0,
                   double start_time = 0);

  // Prints when enough wall time has passed since the last line.
  void update(double sim_time, long steps, double particle_steps_per_second);
  // Ends the live line.
  void finish();

 private:
  double end_time_;
  double start_time_;
  std::FILE* stream_;
  bool live_;
  double interval_;
  std::chrono::steady_clock::time_point start_, last_;
  bool printed_ = false;
};

}  // namespace sluice
