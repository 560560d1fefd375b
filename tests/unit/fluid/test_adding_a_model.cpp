// A model added without touching the engine: registered by name next to the shipped ones,
// built from a case, stepped with a body by the engine and the coupler, with its own field in
// the frames and the engine's probes answering from its particles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "particle_state_of.hpp"
#include "sluice/core/errors.hpp"
#include "sluice/sim/frame_output.hpp"
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
  const std::vector<Vec<2>> start = testing::particle_state(sim).particles.position;
  const double z0 = sim.bodies().state(0).position[2];
  while (sim.time() < 0.2 - 1e-12) sim.step(0.2);
  EXPECT_EQ(sim.clock().step, 20);

  // The block fell freely through the still water (which pushes nothing), its particles with it.
  const double g = 9.81, t = 0.2;
  EXPECT_NEAR(sim.bodies().state(0).position[2], z0 - 0.5 * g * t * t, 1e-9);
  EXPECT_EQ(sim.coupler().fluid_force()[0], Vec3::Zero());
  const auto& ps = testing::particle_state(sim).particles;
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
  const io::PolyFrame frame = frame_of(sim.fluid().observation().view()).points;
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
  const std::vector<double> measured =
      Probes({middle, gauge}, "").measure(sim.fluid().observation());
  EXPECT_NEAR(measured[0], 1000 * g * 0.1, 0.01 * 1000 * g * 0.1);
  EXPECT_NEAR(measured[1], 0.2, 0.02);
}

// The base runs the model's loops and its own services (sort, body points, check, last good
// state, energy) on the emulated device, the model having no device code: the same bits as on
// the host, its own field included.
TEST(AddingAModel, RunsOnTheEmulatedDeviceWithoutCodeOfItsOwnForIt) {
  struct End {
    io::PolyFrame frame, last_good;
    std::vector<Vec<2>> position;  // in double, as the set holds them
    std::vector<Real> depth;
    Vec3 body;
    FluidEnergy energy;
  };
  auto run = [](const std::string& device) {
    Simulation<2> sim(
        still_tank("  name: still_water\n  time_step: 0.01\n  device: " + device + "\n"),
        with_still_water());
    while (sim.time() < 0.2 - 1e-12) {
      sim.step(0.2);
      sim.fluid().guard().remember_good(sim.time());
    }
    EXPECT_EQ(sim.fluid().guard().check(sim.clock()), std::nullopt);
    End end{frame_of(sim.fluid().observation().view()).points,
            frame_of(sim.fluid().guard().last_good_view()).points,
            {},
            {},
            sim.bodies().state(0).position,
            sim.fluid().observation().energy()};
    const auto& ps =
        testing::particle_state(sim).particles;  // the device's copy came back for the frame
    end.position = ps.position;
    end.depth.assign(ps.components<Real>("depth"), ps.components<Real>("depth") + ps.size());
    return end;
  };
  const End host = run("cpu"), device = run("emulated");
  for (io::PolyFrame End::*frames : {&End::frame, &End::last_good}) {
    const io::PolyFrame& a = host.*frames;
    const io::PolyFrame& b = device.*frames;
    EXPECT_EQ(a.points, b.points);
    ASSERT_EQ(a.float_arrays.size(), b.float_arrays.size());
    for (std::size_t k = 0; k < a.float_arrays.size(); ++k) {
      EXPECT_EQ(a.float_arrays[k].name, b.float_arrays[k].name);
      EXPECT_EQ(a.float_arrays[k].values, b.float_arrays[k].values) << a.float_arrays[k].name;
    }
    ASSERT_EQ(a.int_arrays.size(), b.int_arrays.size());
    for (std::size_t k = 0; k < a.int_arrays.size(); ++k) {
      EXPECT_EQ(a.int_arrays[k].values, b.int_arrays[k].values) << a.int_arrays[k].name;
    }
  }
  EXPECT_EQ(host.position, device.position);
  EXPECT_EQ(host.depth, device.depth);
  EXPECT_EQ(host.body, device.body);
  EXPECT_EQ(host.energy.kinetic, device.energy.kinetic);
  EXPECT_EQ(host.energy.potential, device.energy.potential);
  EXPECT_EQ(host.energy.mass, device.energy.mass);
}

// On the emulated device the host's set is a cache: what a frame shows comes from the device.
// (In a tank without bodies nothing reads the host's set between frames.)
TEST(AddingAModel, OnTheEmulatedDeviceTheHostsSetIsACache) {
  const std::string tank =
      "dimension: 2\nspacing: 0.02\ndomain: {min: [0, 0], max: [0.4, 0.6]}\nend_time: 0.2\n"
      "output_interval: 0.1\nfluid:\n  blocks:\n    - {min: [0, 0], max: [0.4, 0.2]}\n"
      "walls:\n  - {type: tank, min: [0, 0], max: [0.4, 0.6], open: [z+]}\n"
      "model: {name: still_water, time_step: 0.01, device: ";
  for (const std::string device : {"cpu", "emulated"}) {
    Simulation<2> sim(io::parse_case(tank + device + "}\n", "still.yaml"), with_still_water());
    sim.step(0.2);
    auto& cache = const_cast<ParticleSet<2>&>(testing::particle_state(sim).particles);
    std::fill_n(cache.components<Real>("depth"), cache.size(), -1.0);
    const io::PolyFrame frame = frame_of(sim.fluid().observation().view()).points;
    const auto depth = std::find_if(frame.float_arrays.begin(), frame.float_arrays.end(),
                                    [](const io::PointArrayF32& a) { return a.name == "depth"; });
    ASSERT_NE(depth, frame.float_arrays.end());
    EXPECT_EQ(*std::max_element(depth->values.begin(), depth->values.end()) > 0,
              device == "emulated")
        << device;
  }
}

}  // namespace
}  // namespace sluice
