// "Still water": the smallest fluid model that plugs into sluice, written outside the engine
// to show what a model implements (docs/adding-a-model.md walks through it). Its fluid stays
// where the engine put it, at rest, with the hydrostatic pressure the engine gave it. It adds a
// field of its own (the depth under the free surface, written in every frame), a stage that
// updates it, and one parameter (its time step). It pushes no body: bodies fall through it.
#pragma once

#include <fmt/format.h>

#include <memory>

#include "sluice/fluid/particle_fluid.hpp"
#include "sluice/io/yaml_reader.hpp"

namespace sluice::example {

template <int D>
class StillWater final : public ParticleFluid<D> {
 public:
  StillWater(const io::CaseConfig& config, const BodyGeometry& bodies, double time_step)
      // Its particles interact with none: any radius will do; two spacings of wall suffice.
      : ParticleFluid<D>(config, 2 * config.spacing, bodies),
        time_step_(time_step),
        rho_g_(config.fluid.density * config.gravity.norm()) {}

  void initialize() override {
    this->state().particles.add_scalar_field({"depth", "m", true});
    measure_depth();
  }
  std::string describe() const override {
    return fmt::format("still_water: time step {} s", time_step_);
  }
  TimeStep next_time_step() const override { return {time_step_, "the test's fixed step"}; }

 protected:
  void model_stages(StageList&, StageList& after_neighbours) override {
    after_neighbours.push_back(
        make_stage<const StepClock>("depth", [this](const StepClock&) { measure_depth(); }));
  }
  void body_point_forces(const std::vector<BodyKinematics>&, std::vector<Vec3>&) const override {
  }  // no force on any body
  // Checkpoints: what the model carries from step to step beyond its particle fields (which
  // the engine saves): nothing here.
  void archive_model(StateArchive&) override {}

 private:
  // p = rho g depth, so depth = p / (rho g): a loop body over plain arrays, which the base runs
  // wherever the particles live (the host, or the emulated device).
  struct DepthOfParticle {
    const Real* pressure;
    const std::int32_t* kind;  // ParticleKind's integer: 0 is fluid
    Real* depth;
    Real rho_g;
    void operator()(std::size_t i) const { depth[i] = kind[i] == 0 ? pressure[i] / rho_g : 0; }
  };
  void measure_depth() {
    this->for_each_particle([&](auto& set) {
      return DepthOfParticle{set.template components<Real>("pressure"),
                             set.template components<std::int32_t>("kind"),
                             set.template components<Real>("depth"), rho_g_};
    });
  }

  double time_step_;
  Real rho_g_;
};

// The factory a registry holds: reads and checks the model's parameters, builds it ready to
// step.
template <int D>
std::unique_ptr<FluidSystem> make_still_water(const io::CaseConfig& config,
                                              const BodyGeometry& bodies, const ModelServices&) {
  io::MapReader model(config.source, config.model, "model", config.model_line);
  model.required<std::string>("name");
  const double time_step = model.required_positive("time_step");
  const std::string device = model.optional_choice("device", "cpu", "device", {"cpu", "emulated"});
  model.finish();  // unknown keys are errors
  auto fluid = std::make_unique<StillWater<D>>(config, bodies, time_step);
  fluid->initialize();
  if (device == "emulated") fluid->run_on_emulated_device();  // the base's, for any model
  return fluid;
}

}  // namespace sluice::example
