// A model added without touching the engine: registered by name next to the shipped ones,
// built from a case, stepped with a body by the engine and the coupler, with its own field in
// the frames and the engine's probes answering from its particles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sluice/core/errors.hpp"
#include "sluice/sim/probes.hpp"
#include "sluice/sim/simulation.hpp"
#include "unit/fluid/still_water_model.hpp"

namespace sluice {
namespace {

io::CaseConfig still_tank(const std::string& model) {
  return io::parse_case(
      "dimension: 2\nspacing: 0.02\ndomain: {min: [0, 0], max: [0.4, 0.6]}\nend_time: 0.2\n"
      "output_interval: 0.1\nfluid:\n  blocks:\n    - {min: [0, 0], max: [0.4, 0.2]}\n"
      "walls:\n  - {type: tank, min: [0, 0], max: [0.4, 0.6], open: [z+]}\n"
      "bodies:\n  - {name: block, shape: box, size: [0.06, 0.06], density: 500, "
      "position: [0.2, 0.45]}\n"
      "model:\n" +
          model,
      "still.yaml");
}

ModelRegistry with_still_water() {
  ModelRegistry models = shipped_models<2>();
  models.add("still_water", example::make_still_water<2>);
  return models;
}

TEST(AddingAModel, RegisteredNextToTheShippedOnes) {
  const ModelRegistry models = with_still_water();
  EXPECT_EQ(models.names(), (std::vector<std::string>{"constraint", "granular", "mac", "mps",
                                                      "penalty-sph", "still_water", "wcsph"}));
  try {
    Simulation<2> sim(still_tank("  name: stil_water\n"), models);
    FAIL() << "an unknown model must be an input error";
  } catch (const InputError& e) {
    EXPECT_NE(
        std::string(e.what()).find("expected one of: constraint, granular, mac, mps, penalty-sph, "
                                   "still_water, wcsph (did you mean "
                                   "'still_water'?)"),
        std::string::npos)
        << e.what();
  }
  EXPECT_THROW(Simulation<2>(still_tank("  name: still_water\n"), models), InputError);
}

TEST(AddingAModel, TheEngineStepsItWithABody) {
  Simulation<2> sim(still_tank("  name: still_water\n  time_step: 0.01\n"), with_still_water());
  EXPECT_EQ(sim.fluid().describe(), "still_water: time step 0.01 s");
  const std::vector<Vec<2>> start = sim.state().particles.position;
  const double z0 = sim.bodies().state(0).position[2];
  while (sim.time() < 0.2 - 1e-12) sim.step(0.2);
  EXPECT_EQ(sim.clock().step, 20);

  // The block fell freely through the still water (which pushes nothing), its particles with it.
  const double g = 9.81, t = 0.2;
  EXPECT_NEAR(sim.bodies().state(0).position[2], z0 - 0.5 * g * t * t, 1e-9);
  EXPECT_EQ(sim.coupler().fluid_force()[0], Vec3::Zero());
  const auto& ps = sim.state().particles;
  double lowest_body_point = 1;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (ps.kind[i] == ParticleKind::kBody)
      lowest_body_point = std::min(lowest_body_point, ps.position[i][1]);
  }
  EXPECT_LT(lowest_body_point, 0.45 - 0.5 * g * t * t);

  // The fluid stayed where it was (the neighbour sort reorders it; compare as sets of heights).
  double highest = 0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (ps.is_fluid(i)) highest = std::max(highest, ps.position[i][1]);
  }
  double highest_at_start = 0;
  for (const auto& x : start) highest_at_start = std::max(highest_at_start, x[1]);
  EXPECT_LE(highest, highest_at_start);

  // Its own field is in the frame, beside the engine's, and holds the depth.
  const io::PolyFrame frame = sim.fluid().frame().points;
  const auto depth = std::find_if(frame.float_arrays.begin(), frame.float_arrays.end(),
                                  [](const io::PointArrayF32& a) { return a.name == "depth"; });
  ASSERT_NE(depth, frame.float_arrays.end());
  const float deepest = *std::max_element(depth->values.begin(), depth->values.end());
  EXPECT_NEAR(deepest, 0.2 - 0.01, 1e-4);  // the lowest particles, half a spacing up

  // Its stage is timed with the engine's.
  const auto stages = sim.timers().entries();
  EXPECT_TRUE(std::any_of(stages.begin(), stages.end(),
                          [](const StageTimers::Entry& e) { return e.name == "depth"; }));

  // The engine's probes read its particles: the pressure at mid-depth (where the Shepard
  // average is symmetric) and the water's height.
  io::ProbeConfig middle, gauge;
  middle.kind = io::ProbeKind::kPressure;
  middle.point = Vec3(0.1, 0, 0.1);
  gauge.kind = io::ProbeKind::kWaterHeight;
  gauge.point = Vec3(0.1, 0, 0);
  const std::vector<double> measured = Probes({middle, gauge}, "").measure(sim.fluid());
  EXPECT_NEAR(measured[0], 1000 * g * 0.1, 0.01 * 1000 * g * 0.1);
  EXPECT_NEAR(measured[1], 0.2, 0.02);
}

}  // namespace
}  // namespace sluice
