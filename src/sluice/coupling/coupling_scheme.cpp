#include "sluice/coupling/coupling_scheme.hpp"

#include <algorithm>
#include <stdexcept>

#include "sluice/coupling/coupler.hpp"

namespace sluice {

namespace {

class HeldLoads final : public CouplingScheme {
 public:
  const char* name() const override { return "held-loads"; }
  void advance(Coupler& coupler, double dt) const override {
    coupler.record_step(coupler.exchange(dt, FluidLoads::kHeld), 1);
  }
};

class SpringExchanges final : public CouplingScheme {
 public:
  const char* name() const override { return "spring-exchanges"; }
  void advance(Coupler& coupler, double dt) const override {
    const int pieces = std::max(1, coupler.exchanges(dt));
    const double h = dt / pieces;
    int substeps = 0;
    for (int e = 0; e < pieces; ++e) {
      if (e > 0) coupler.collect_loads();
      substeps += coupler.exchange(h, FluidLoads::kHeld);
    }
    coupler.record_step(substeps, pieces);
  }
};

class Monolithic final : public CouplingScheme {
 public:
  const char* name() const override { return "monolithic"; }
  void advance(Coupler& coupler, double dt) const override {
    coupler.record_step(coupler.exchange(dt, FluidLoads::kInSolve), 1);
  }
  bool solves_without_bodies() const override { return true; }
};

class Projection final : public CouplingScheme {
 public:
  const char* name() const override { return "projection"; }
  void advance(Coupler& coupler, double dt) const override {
    coupler.record_step(coupler.exchange(dt, FluidLoads::kLeftOut), 1);
  }
  bool fluid_solves_body_velocities() const override { return true; }
};

}  // namespace

StageList CouplingScheme::assemble_step(StageList before_bodies, StageList after_bodies,
                                        Coupler& coupler, bool has_bodies, bool has_fluid) const {
  StageList step = std::move(before_bodies);
  if (has_bodies || (has_fluid && solves_without_bodies())) {
    step.push_back(make_stage<const StepClock>(
        "bodies", [this, &coupler](const StepClock& c) { advance(coupler, c.dt); }));
  }
  for (auto& stage : after_bodies) step.push_back(std::move(stage));
  if (has_fluid && has_bodies && fluid_solves_body_velocities()) {
    step.push_back(make_stage<const StepClock>("body_velocities", [&coupler](const StepClock& c) {
      coupler.take_solved_velocities(c.dt);
    }));
  }
  if (has_fluid && has_bodies) {
    step.push_back(make_stage<const StepClock>(
        "body_loads", [&coupler](const StepClock&) { coupler.collect_loads(); }));
    coupler.collect_loads();
  }
  return step;
}

std::vector<std::string> coupling_scheme_names() {
  return {"held-loads", "spring-exchanges", "monolithic", "projection"};
}

std::unique_ptr<CouplingScheme> make_coupling_scheme(const std::string& name) {
  if (name == "held-loads") return std::make_unique<HeldLoads>();
  if (name == "spring-exchanges") return std::make_unique<SpringExchanges>();
  if (name == "monolithic") return std::make_unique<Monolithic>();
  if (name == "projection") return std::make_unique<Projection>();
  throw std::invalid_argument("no coupling scheme '" + name + "'");
}

}  // namespace sluice
