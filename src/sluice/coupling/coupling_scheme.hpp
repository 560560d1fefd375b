// How a fluid and the bodies take a step together: the order of the step's stages, and what
// the bodies' advance exchanges with the fluid. A model declares the schemes it supports (its
// registry entry); the case picks one with `coupling.scheme` (docs/case-format.md).
//   held-loads        explicit co-simulation (seed 000): in each fluid step the bodies advance
//                     first, over as many solid sub-steps as their contacts need, with the
//                     fluid's last loads held; the fluid then sees them where they now are,
//                     evaluates its forces, and hands back the loads for the next step.
//   spring-exchanges  a fluid that holds the bodies on stiff springs (penalty-sph): the step is
//                     split into exchanges short enough for the lightest free body on one
//                     spring; after each, the fluid moves with the bodies and hands back its
//                     loads.
//   monolithic        the fluid joins every velocity-level solve of the bodies with its rows,
//                     or with bodies and contacts of its own (rigid/ccp_participant.hpp); its
//                     loads are reported, not held. It runs the bodies' solve even in a case
//                     without bodies (a granular fluid's spheres move in it).
//   projection        a fluid that solves the bodies' velocities with its pressure (the grid's
//                     projection; Batty, Bertails & Bridson 2007): the bodies advance without
//                     the fluid's loads (gravity, contacts, joints), the fluid's pressure solve
//                     takes their velocities as unknowns through their joined mobility (joints
//                     kept), and the bodies take the velocities it solved in the same step; its
//                     loads are reported, not held.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sluice/core/stage.hpp"

namespace sluice {

class Coupler;

class CouplingScheme {
 public:
  virtual ~CouplingScheme() = default;
  virtual const char* name() const = 0;
  // Advances the bodies by dt, and a fluid that moves with them, through the coupler's
  // exchanges.
  virtual void advance(Coupler& coupler, double dt) const = 0;
  // Whether the step runs the bodies' solve in a case without bodies.
  virtual bool solves_without_bodies() const { return false; }
  // Whether the fluid solves the bodies' velocities, which they take after its stages.
  virtual bool fluid_solves_body_velocities() const { return false; }

  // The step's stages in order: the fluid's before the bodies, the bodies' advance (where the
  // case has bodies, or the scheme solves without them), the fluid's after, the velocities the
  // fluid solved given to the bodies (projection), and the loads taken back for the next step
  // (where a fluid acts on bodies: taken once now, too).
  StageList assemble_step(StageList before_bodies, StageList after_bodies, Coupler& coupler,
                          bool has_bodies, bool has_fluid) const;
};

// The names of the schemes, in the order above.
std::vector<std::string> coupling_scheme_names();
// The scheme of that name (one of coupling_scheme_names(); std::invalid_argument otherwise).
std::unique_ptr<CouplingScheme> make_coupling_scheme(const std::string& name);

}  // namespace sluice
