#include "sluice/sim/step_collapse.hpp"

#include <fmt/format.h>

#include <cmath>

namespace sluice {

std::optional<std::string> collapsed_step(const TimeStep& step, const TimeStep& first, double time,
                                          double end_time, const std::string& model) {
  const double steps_left = (end_time - time) / step.dt;
  std::string why;
  if (!(step.dt > 0) || !std::isfinite(steps_left) || steps_left > kMostSteps) {
    why = fmt::format("the {:.3g} s left would take {:.3g} steps, more than {:.0e}",
                      end_time - time, steps_left, kMostSteps);
  } else if (step.dt < kCollapseFraction * first.dt) {
    why = fmt::format("below {:.0e} of the first step ({:.3g} s)", kCollapseFraction, first.dt);
  } else {
    return std::nullopt;
  }
  return fmt::format("the time step collapsed to {:.3g} s, limited by {} in the {} model: {}",
                     step.dt, step.limit, model, why);
}

}  // namespace sluice
