// What the device runs' tests share: a run to its end as the output sees it, and the check that
// a run on the emulated device (`model.device: emulated`) is the CPU's run bit for bit.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "particle_state_of.hpp"
#include "physics_support.hpp"

namespace sluice {
namespace testing {

// What a run ends with: the particles (as output sees them), the bodies and their loads.
template <int D>
struct RunEnd {
  std::vector<Vec<D>> position, velocity;
  std::vector<Real> density, pressure;
  std::vector<Vec3> body_position, fluid_force;
  FluidEnergy energy;
  long steps = 0;
};

template <int D>
inline RunEnd<D> run_to(const io::CaseConfig& config, double end,
                        const std::function<void(const ParticleSet<D>&)>& after_each_step = {}) {
  Simulation<D> sim(config);
  RunEnd<D> out;
  run_until(sim, end, [&](const StepClock&) {
    ++out.steps;
    if (!after_each_step) return;
    sim.fluid().observation().view();  // the device's copy comes back first, as below
    after_each_step(particle_state(sim).particles);
  });
  out.energy = sim.fluid().observation().energy();  // on a device, summed there
  sim.fluid().observation().view();  // a reader of the particles: the device's copy comes back
  const auto& ps = particle_state(sim).particles;
  out.position = ps.position;
  out.velocity = ps.velocity;
  out.density = ps.density;
  out.pressure = ps.pressure;
  for (std::size_t b = 0; b < sim.bodies().count(); ++b) {
    out.body_position.push_back(sim.bodies().state(b).position);
    out.fluid_force.push_back(sim.coupler().fluid_force()[b]);
  }
  return out;
}

// The overrides and the emulated device. (Not inlined: GCC 12 inlines the string's copy into
// the caller and warns, wrongly, that it writes past the string.)
[[gnu::noinline]] inline std::vector<std::string> on_emulated_device(
    std::vector<std::string> overrides) {
  overrides.emplace_back("model.device=emulated");
  return overrides;
}

template <int D>
inline void expect_same_bits(const std::string& file, const std::vector<std::string>& overrides,
                             double end) {
  const std::vector<std::string> on_device = on_emulated_device(overrides);
  const RunEnd<D> cpu = run_to<D>(load_case(file, overrides), end);
  const RunEnd<D> device = run_to<D>(load_case(file, on_device), end);
  ASSERT_GT(cpu.steps, 10) << file;
  EXPECT_EQ(device.steps, cpu.steps) << file;
  ASSERT_EQ(device.position.size(), cpu.position.size()) << file;
  std::size_t differ = 0;
  for (std::size_t i = 0; i < cpu.position.size(); ++i) {
    if (device.position[i] != cpu.position[i] || device.velocity[i] != cpu.velocity[i] ||
        device.density[i] != cpu.density[i] || device.pressure[i] != cpu.pressure[i])
      ++differ;
  }
  EXPECT_EQ(differ, 0u) << file << ": particles that differ after " << cpu.steps << " steps";
  EXPECT_EQ(device.body_position, cpu.body_position) << file;
  EXPECT_EQ(device.fluid_force, cpu.fluid_force) << file;
  EXPECT_EQ(device.energy.kinetic, cpu.energy.kinetic) << file;
  EXPECT_EQ(device.energy.potential, cpu.energy.potential) << file;
  EXPECT_EQ(device.energy.mass, cpu.energy.mass) << file;
  EXPECT_EQ(device.energy.elastic, cpu.energy.elastic) << file;
}

}  // namespace testing
}  // namespace sluice
