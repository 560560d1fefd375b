#include "sluice/sim/divergence_guard.hpp"

#include <fmt/format.h>

#include "sluice/core/errors.hpp"

namespace sluice {

namespace {
const char* problem_of(const RigidBody& body, const AxisBox& escape_box, int dimension) {
  if (!body.position.allFinite() || !body.velocity.allFinite() ||
      !body.orientation.coeffs().allFinite() || !body.angular_momentum.allFinite()) {
    return "its state is not finite";
  }
  if (!escape_box.contains(body.position, dimension)) return "it left the domain";
  return nullptr;
}
}  // namespace

std::optional<std::string> DivergenceGuard::check(const StepClock& clock, const FluidGuard& fluid,
                                                  const RigidBodies& bodies) const {
  // A body first: when one breaks, its particles break with it, and its name says more.
  for (std::size_t b = 0; b < bodies.count(); ++b) {
    if (const char* problem = problem_of(bodies.state(b), escape_box_, dimension_)) {
      const Vec3& x = bodies.state(b).position;
      return diverged_at(clock.step, clock.time) +
             fmt::format("body '{}' at ({:.4g}, {:.4g}, {:.4g}): {}", bodies.config(b).name, x[0],
                         x[1], x[2], problem);
    }
  }
  return fluid.check(clock);
}

}  // namespace sluice
