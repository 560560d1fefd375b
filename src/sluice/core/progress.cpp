#include "sluice/core/progress.hpp"

#include <fmt/format.h>

namespace sluice {

ProgressReporter::ProgressReporter(double end_time, std::FILE* stream, bool live,
                                   double plain_interval, double start_time)
    : end_time_(end_time),
      start_time_(start_time),
      stream_(stream),
      live_(live),
      interval_(live ? 0.25 : plain_interval),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

void ProgressReporter::update(double sim_time, long steps, double particle_steps_per_second) {
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - last_).count() < interval_) return;
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double fraction = end_time_ > 0 ? sim_time / end_time_ : 1;
  // The pace of this run's own stretch, from where it started.
  const double done =
      end_time_ > start_time_ ? (sim_time - start_time_) / (end_time_ - start_time_) : 1;
  const double eta = done > 0 ? elapsed * (1 - done) / done : 0;
  const std::string line = fmt::format(
      "t = {:.4f} / {:.4g} s ({:3.0f} %)  steps {}  {:.3g} M particle-steps/s  ETA {:.0f} s",
      sim_time, end_time_, 100 * fraction, steps, particle_steps_per_second / 1e6, eta);
  if (live_) {
    fmt::print(stream_, "\r{}\033[K", line);
  } else {
    fmt::print(stream_, "{}\n", line);
  }
  std::fflush(stream_);
  printed_ = true;
}

void ProgressReporter::finish() {
  if (live_ && printed_) fmt::print(stream_, "\n");
  std::fflush(stream_);
}

}  // namespace sluice
