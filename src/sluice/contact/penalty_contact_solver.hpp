// The penalty contact solver (seed 000: Amaro Junior, Cheng & Osello 2019): each particle pair
// of a contact carries the bodies' Hertz law (hertz_mindlin.hpp) at its own overlap, with the
// dashpot of its own normal velocity, times its share of the pairs' area: a face pressed
// evenly follows the Hertz-Mindlin law of the bodies whatever the number of pairs, a tilt
// shifts the force to the deeper side, and rocking is damped. One Mindlin spring per contact
// carries the friction. The stiff springs need solid sub-steps: a `substep_fraction` of the
// shortest contact period in reach.
#pragma once

#include <cstdint>
#include <map>

#include "sluice/contact/contact_solver.hpp"
#include "sluice/contact/hertz_mindlin.hpp"

namespace sluice {

class PenaltyContactSolver final : public ContactSolver {
 public:
  PenaltyContactSolver(Vec3 gravity, double substep_fraction)
      : gravity_(gravity), substep_fraction_(substep_fraction) {}

  bool in_velocity_step() const override { return false; }
  void solve(ContactSet& contacts, const std::vector<SystemBody>& bodies,
             const std::vector<ContactShape>& shapes, double dt, std::vector<Vec3>& force,
             std::vector<Vec3>& torque) override;
  double pair_step(std::size_t a, std::size_t b, double approach,
                   const std::vector<SystemBody>& bodies,
                   const std::vector<ContactShape>& shapes) override;
  double stored_energy() const override { return elastic_energy_; }
  // The deepest overlap of the last solve sizes the next sub-step; the laws and the damping
  // table are caches of pure functions of the case.
  void archive_state(StateArchive& a) override {
    a(elastic_energy_, deepest_overlap_, deepest_overlap_ever_);
  }
  // The deepest overlap at any solve so far.
  double deepest_overlap_ever() const override { return deepest_overlap_ever_; }
  Figures figures() const override {
    return {elastic_energy_, deepest_overlap_, deepest_overlap_ever_};
  }
  void set_figures(const Figures& f) override {
    elastic_energy_ = f.stored_energy;
    deepest_overlap_ = f.deepest_overlap;
    deepest_overlap_ever_ = f.deepest_overlap_ever;
  }

 private:
  const ContactPair& law(std::size_t a, std::size_t b, const std::vector<SystemBody>& bodies,
                         const std::vector<ContactShape>& shapes);

  Vec3 gravity_;
  double substep_fraction_;
  std::map<std::uint64_t, ContactPair> laws_;  // per body pair
  HertzDampingTable damping_;
  double elastic_energy_ = 0;
  double deepest_overlap_ = 0;
  double deepest_overlap_ever_ = 0;
};

}  // namespace sluice
