// A time step that collapses stops the run as diverged instead of running for ever: a step below
// a ten-thousandth of the first one, or one so small that the rest of the run would take more
// than a billion steps (an absurd gravity or viscosity gives that from the start).
#pragma once

#include <optional>
#include <string>

#include "sluice/core/time_step.hpp"

namespace sluice {

inline constexpr double kCollapseFraction = 1e-4;
inline constexpr double kMostSteps = 1e9;

// Why `step`, taken at `time` by `model`, has collapsed (empty when it has not), against the
// run's `first` step and its `end_time`.
std::optional<std::string> collapsed_step(const TimeStep& step, const TimeStep& first, double time,
                                          double end_time, const std::string& model);

}  // namespace sluice
