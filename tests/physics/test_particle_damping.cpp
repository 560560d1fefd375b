// Damping zones for the particle models (docs/case-format.md, "Damping zones"): a block of water
// without gravity or walls, moving at 0.5 m/s inside a zone whose rate is `strength` all over it.
// The pair forces of wcsph and penalty-sph add up to nothing, and mps's pressure stays at rest in
// this uniform motion, so the water's momentum decays as exp(-strength t): held to 1e-5 (measured
// to the eighth digit with every model).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "physics_support.hpp"
#include "sluice/fluid/particle_fluid.hpp"

namespace sluice {
namespace {

using testing::load_case;
using testing::run_until;

// The fluid's mean velocity along x.
double mean_speed(const ParticleFluid<2>& fluid) {
  const auto& ps = fluid.state().particles;
  double momentum = 0, mass = 0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (!ps.is_fluid(i)) continue;
    momentum += ps.mass[i] * ps.velocity[i][0];
    mass += ps.mass[i];
  }
  return momentum / mass;
}

struct DampedModel {
  std::string name;   // the test's
  std::string model;  // the case's `model` mapping
  double tolerance;   // relative, on the mean speed
};

class DampingZones : public ::testing::TestWithParam<DampedModel> {};

TEST_P(DampingZones, DecayTheWatersMomentumAtTheirRate) {
  const double strength = 2, end = 0.5, speed = 0.5;
  Simulation<2> sim(load_case(
      "hydrostatic_2d.yaml",
      {"gravity=[0, 0]", "spacing=0.05", "domain={min: [0, 0], max: [3, 2]}", "walls=[]",
       "probes=[]", "fluid.blocks.0.min=[1, 0.5]", "fluid.blocks.0.max=[2, 1.5]",
       "fluid.blocks.0.velocity=[0.5, 0]", "damping=[{axis: x, from: 0, to: 0.001, strength: 2}]",
       "model=" + GetParam().model}));
  const auto& fluid = dynamic_cast<const ParticleFluid<2>&>(sim.fluid());
  run_until(sim, end, [](const StepClock&) {});
  const double expected = speed * std::exp(-strength * sim.time());
  std::printf("%s: mean speed %.8f m/s after %.4f s, exp(-s t) gives %.8f\n",
              GetParam().name.c_str(), mean_speed(fluid), sim.time(), expected);
  EXPECT_NEAR(mean_speed(fluid), expected, GetParam().tolerance * expected) << GetParam().model;
}

INSTANTIATE_TEST_SUITE_P(
    ParticleModels, DampingZones,
    ::testing::Values(DampedModel{"wcsph", "{name: wcsph, sound_speed: 20}", 1e-5},
                      DampedModel{"penalty_sph", "{name: penalty-sph, max_speed: 2}", 1e-5},
                      DampedModel{"mps", "{name: mps, max_speed: 2}", 1e-5}),
    [](const ::testing::TestParamInfo<DampedModel>& info) { return info.param.name; });

}  // namespace
}  // namespace sluice
