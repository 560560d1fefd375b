#include "sluice/sim/divergence_guard.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "sluice/exec/policy.hpp"
#include "sluice/sim/frame_output.hpp"

namespace sluice {

namespace {
template <int D>
const char* problem_of(const ParticleState<D>& s, std::size_t i) {
  const auto& ps = s.particles;
  if (!ps.position[i].allFinite()) return "its position is not finite";
  if (!ps.velocity[i].allFinite()) return "its velocity is not finite";
  if (!std::isfinite(ps.density[i]) || !std::isfinite(ps.pressure[i])) {
    return "its density or pressure is not finite";
  }
  if (ps.is_fluid(i) && !s.escape_box.contains(to_3d<D>(ps.position[i]), D))
    return "it left the domain";
  return nullptr;
}

const char* problem_of(const RigidBody& body, const AxisBox& escape_box, int dimension) {
  if (!body.position.allFinite() || !body.velocity.allFinite() ||
      !body.orientation.coeffs().allFinite() || !body.angular_momentum.allFinite()) {
    return "its state is not finite";
  }
  if (!escape_box.contains(body.position, dimension)) return "it left the domain";
  return nullptr;
}

template <int D>
std::string where(const ParticleState<D>& s, const std::string& what, const Vec3& x) {
  return fmt::format("the run diverged at step {}, t = {:.6g} s: {} at ({:.4g}, {:.4g}, {:.4g})",
                     s.step, s.time, what, x[0], x[1], x[2]);
}
}  // namespace

template <int D>
std::optional<std::string> DivergenceGuard<D>::check(const ParticleState<D>& s,
                                                     const RigidBodies& bodies) const {
  // A body first: when one breaks, its points break with it, and its name says more.
  for (std::size_t b = 0; b < bodies.count(); ++b) {
    if (const char* problem = problem_of(bodies.state(b), s.escape_box, D)) {
      return where(s, fmt::format("body '{}'", bodies.config(b).name), bodies.state(b).position) +
             ": " + problem;
    }
  }
  // The first bad particle by index, found in parallel; the same on any thread count.
  const double first = -exec::Default::max_of(s.particles.size(), [&](std::size_t i) {
    return problem_of(s, i) ? -static_cast<double>(i) : -std::numeric_limits<double>::infinity();
  });
  if (!std::isfinite(first)) return std::nullopt;
  const auto i = static_cast<std::size_t>(first);
  const Vec3 x = to_3d<D>(s.particles.position[i]);
  return where(s, fmt::format("particle {}", i), x) + ": " + problem_of(s, i);
}

template <int D>
void DivergenceGuard<D>::remember(const ParticleState<D>& s) {
  // What a frame shows, the model's fields marked for output included; the first time, a
  // whole copy that gives the set its fields.
  if (!holds_fields_) {
    last_good_ = s.particles;
    holds_fields_ = true;
  }
  last_good_.assign_fields(s.particles, FrameOutput::shows);
  last_good_time_ = s.time;
}

template class DivergenceGuard<2>;
template class DivergenceGuard<3>;

}  // namespace sluice
