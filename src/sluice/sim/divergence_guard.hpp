// Stops a run that has gone wrong: a body whose state is not finite or whose centre of mass
// left the domain, a particle with a non-finite position, velocity, density or pressure, or a
// fluid particle outside the domain. Keeps a copy of the last good state, so the frame written
// on the way out shows the flow just before it broke.
#pragma once

#include <optional>
#include <string>

#include "sluice/fluid/particle_state.hpp"
#include "sluice/sim/rigid_bodies.hpp"

namespace sluice {

template <int D>
class DivergenceGuard {
 public:
  // The problem with the state, or nothing when it is sound.
  std::optional<std::string> check(const ParticleState<D>& s, const RigidBodies& bodies) const;

  // Remembers `s` as the last good state.
  void remember(const ParticleState<D>& s);

  const ParticleSet<D>& last_good() const { return last_good_; }
  double last_good_time() const { return last_good_time_; }

 private:
  ParticleSet<D> last_good_;
  double last_good_time_ = 0;
  bool holds_fields_ = false;
};

}  // namespace sluice
