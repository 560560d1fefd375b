// The order of the exchanges between a fluid and the rigid bodies. Explicit co-simulation
// (seed 000): in each fluid step the bodies advance first, over as many solid sub-steps as
// their contacts need, with the fluid's last load held; the fluid then sees the bodies where
// they now are, evaluates its forces, and hands back the loads for the next step. Without
// sub-cycling, the fluid itself steps at the solid step whenever a contact is in reach (the
// reference of C6). Monolithic (a fluid whose scheme says so): the fluid joins every
// velocity-level solve of the bodies with its rows, or its own bodies and contacts
// (rigid/ccp_participant.hpp); its loads are then reported, not held. A fluid that holds the bodies
// on stiff springs (penalty-sph) asks for several exchanges within its step: the bodies advance
// piece by piece, and the fluid moves with them after each piece and hands back its loads.
#pragma once

#include <vector>

#include "sluice/contact/multibody_system.hpp"
#include "sluice/core/time_step.hpp"
#include "sluice/coupling/fluid_exchange.hpp"

namespace sluice {

class Coupler {
 public:
  // The first `bodies` bodies of `system` are the case's bodies (the rest are walls); `fluid`
  // may be null (bodies alone). Both must outlive the coupler.
  Coupler(MultibodySystem& system, std::size_t bodies, FluidExchange* fluid, bool subcycling);

  // The step the coupled system takes when the fluid asks for `fluid` (without sub-cycling, a
  // contact's shorter step limits it).
  TimeStep time_step(TimeStep fluid);
  // Advances the bodies by dt with the held loads, then hands the fluid their motion.
  void advance_bodies(double dt);
  // Takes the fluid's loads on the bodies, to hold over the next advance.
  void collect_loads();

  const std::vector<BodyKinematics>& motion() const { return motion_; }
  // The fluid's force and moment (about the centre of mass) on each body, as held.
  const std::vector<Vec3>& fluid_force() const { return fluid_force_; }
  const std::vector<Vec3>& fluid_moment() const { return fluid_moment_; }
  int most_substeps() const { return most_substeps_; }
  // The most exchanges a step took (boundary springs; FluidExchange::boundary_stiffness).
  int most_exchanges() const { return most_exchanges_; }
  // The exchanges a step of dt takes: 1, or with a fluid that holds the bodies on springs,
  // enough that omega h stays below kExchangeAngle for the lightest free body.
  int exchanges(double dt) const;
  // Checkpoints: the held loads, the motion handed to the fluid, the statistics.
  void archive_state(StateArchive& a) {
    a.section("coupler");
    a(motion_, fluid_force_, fluid_moment_, most_substeps_, most_exchanges_);
  }
  // A load held over an exchange of length h lags the body's motion; on a spring of frequency
  // omega that stays stable while omega h is below about 1 per spring on the body. Measured on
  // seed 002's free granular bed: omega h = 1 diverges, 0.5 holds; 0.25 keeps a factor 4.
  static constexpr double kExchangeAngle = 0.25;

 private:
  void update_motion(double dt);

  MultibodySystem& system_;
  std::size_t bodies_;
  FluidExchange* fluid_;
  bool subcycling_;
  std::vector<BodyKinematics> motion_;
  std::vector<Vec3> fluid_force_, fluid_moment_;
  int most_substeps_ = 0;
  int most_exchanges_ = 1;
};

}  // namespace sluice
