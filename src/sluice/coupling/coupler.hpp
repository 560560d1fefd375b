// What a fluid and the rigid bodies exchange, and when: the bodies' motion handed to the fluid,
// the fluid's loads held for the bodies, and the step's order, which the coupling scheme
// (coupling_scheme.hpp) owns. Without sub-cycling, the fluid itself steps at the solid step
// whenever a contact is in reach (the reference of C6).
#pragma once

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "sluice/contact/multibody_system.hpp"
#include "sluice/core/time_step.hpp"
#include "sluice/coupling/coupling_scheme.hpp"
#include "sluice/coupling/fluid_exchange.hpp"

namespace sluice {

// What the bodies' advance in an exchange does with the fluid's loads: holds the last ones
// (co-simulation), has the fluid in its solve (monolithic), or leaves them out (the fluid
// gives the bodies its solved velocities after its own stages: projection).
enum class FluidLoads { kHeld, kInSolve, kLeftOut };

class Coupler {
 public:
  // The first `bodies` bodies of `system` are the case's bodies (the rest are walls); `fluid`
  // may be null (bodies alone). Both must outlive the coupler. `scheme`: a name of
  // coupling_scheme_names().
  Coupler(MultibodySystem& system, std::size_t bodies, FluidExchange* fluid, bool subcycling,
          const std::string& scheme = "held-loads");

  const CouplingScheme& scheme() const { return *scheme_; }
  // The step's stages as the scheme orders them (CouplingScheme::assemble_step).
  StageList assemble_step(StageList before_bodies, StageList after_bodies, bool has_bodies,
                          bool has_fluid) {
    return scheme_->assemble_step(std::move(before_bodies), std::move(after_bodies), *this,
                                  has_bodies, has_fluid);
  }

  // The step the coupled system takes when the fluid asks for `fluid` (without sub-cycling, a
  // contact's shorter step limits it).
  TimeStep time_step(TimeStep fluid);
  // Advances the bodies by dt as the scheme exchanges with the fluid.
  void advance_bodies(double dt) { scheme_->advance(*this, dt); }
  // Takes the fluid's loads on the bodies, to hold over the next advance.
  void collect_loads();

  // The schemes' exchange: advances the bodies by h, with the fluid's loads as `loads` says,
  // then hands the fluid their motion and lets a fluid that moves with them do so. Returns the
  // solid sub-steps it took.
  int exchange(double h, FluidLoads loads);
  // The projection scheme, after the fluid's stages of a step of dt: each free body takes the
  // velocity the fluid solved (FluidExchange::solved_body_velocities), and the motion handed
  // on (its accelerations) includes the change.
  void take_solved_velocities(double dt);
  // A step took `substeps` solid sub-steps in `exchanges` exchanges (the statistics).
  void record_step(int substeps, int exchanges) {
    most_substeps_ = std::max(most_substeps_, substeps);
    most_exchanges_ = std::max(most_exchanges_, exchanges);
  }

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
  std::unique_ptr<CouplingScheme> scheme_;
  std::vector<BodyKinematics> motion_;
  std::vector<Vec3> fluid_force_, fluid_moment_;
  int most_substeps_ = 0;
  int most_exchanges_ = 1;
};

}  // namespace sluice
