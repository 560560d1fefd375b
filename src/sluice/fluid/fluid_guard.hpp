// How a fluid helps the run's divergence guard (sim/divergence_guard.hpp): it says what is
// wrong with it, if anything, and keeps its last good state, whose fields the run writes as
// its last frame when a step goes wrong.
#pragma once

#include <optional>
#include <string>

#include "sluice/core/stage.hpp"
#include "sluice/fluid/fluid_view.hpp"

namespace sluice {

class FluidGuard {
 public:
  virtual ~FluidGuard() = default;

  // What is wrong with the fluid, if anything (the message names the place).
  virtual std::optional<std::string> check(const StepClock& clock) const = 0;
  // Keeps the present state as the last good one.
  virtual void remember_good(double time) = 0;
  virtual FluidView last_good_view() const = 0;
  virtual double last_good_time() const = 0;
};

}  // namespace sluice
