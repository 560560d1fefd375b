// The WCSPH device run (issue 16). On the host's threads (`model.device: emulated`) it runs the
// loop bodies the CPU path runs, in the same order, over its own copy of the particles with its
// own sort, scans, gathers and transfers: it must give the CPU's answer bit for bit. On a GPU
// (`model.device: gpu`) the same loop bodies run as CUDA kernels, whose rounding differs (fused
// multiply-adds, another order of the reductions), so the answers must agree with the CPU's
// within the tolerances of the physics checks: F1, F2, B1 and the bench case's front and
// energy. The GPU checks are skipped where this build or this machine has no GPU.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "physics_support.hpp"
#if defined(SLUICE_WITH_CUDA)
#include "sluice/exec/cuda_backend_check.hpp"
#endif
#include "device_run_support.hpp"
#include "particle_state_of.hpp"
#include "sluice/fluid/wcsph/wcsph_device_run.hpp"
#include "sluice/sim/probes.hpp"
#include "sluice/sim/size_estimate.hpp"

namespace sluice {
namespace {

using testing::expect_same_bits;
using testing::run_to;
using testing::RunEnd;

TEST(WcsphDevice, EmulatedRunIsTheCpuRunBitForBit) {
  expect_same_bits<2>("dam_break_2d.yaml", {"spacing=0.05"}, 0.3);
  // A floating body: its points move with it, its load comes back from the device.
  expect_same_bits<2>("floating_box_2d.yaml", {}, 0.3);
  // 3D, with five bodies on joints and wheels resting in the water.
  expect_same_bits<3>("fording.yaml", {}, 0.05);
}

// Waiting for the device at the end of every stage, for the stages' times, changes no answer
// (and the key is accepted, with no effect, on the CPU too).
TEST(WcsphDevice, TimedStagesGiveTheSameAnswer) {
  expect_same_bits<2>("dam_break_2d.yaml", {"spacing=0.05", "model.time_device_stages=true"}, 0.1);
}

// Water thrown at the floor at 6 m/s: the particles that reach the floor's layers are put back on
// its surface, on the device as on the CPU (wall_surfaces.hpp), to the same bits.
TEST(WcsphDevice, WaterThrownAtTheFloorIsKeptOutOfItOnTheDeviceToo) {
  const std::string text =
      "dimension: 2\nspacing: 0.02\ndomain: {min: [0, 0], max: [0.4, 0.4]}\nend_time: 1\n"
      "output_interval: 0.1\nfluid:\n  blocks:\n"
      "    - {min: [0, 0], max: [0.4, 0.1], velocity: [0, -6]}\n"
      "walls:\n  - {type: tank, min: [0, 0], max: [0.4, 0.4], open: [z+]}\n";
  const io::CaseConfig cpu_case = io::parse_case(text + "model: {name: wcsph}\n", "thrown.yaml");
  const io::CaseConfig device_case =
      io::parse_case(text + "model: {name: wcsph, device: emulated}\n", "thrown.yaml");
  const RunEnd<2> cpu = run_to<2>(cpu_case, 0.01);
  // Away from the corners, where a particle behind a side and the floor goes back through the
  // one it is deeper behind: fluid particles on the floor's surface and below it, every step.
  int on_floor = 0, below = 0;
  const RunEnd<2> device = run_to<2>(device_case, 0.01, [&](const ParticleSet<2>& ps) {
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (!ps.is_fluid(i) || ps.position[i][0] < 0.05 || ps.position[i][0] > 0.35) continue;
      below += ps.position[i][1] < 0;
      on_floor += ps.position[i][1] == 0;
    }
  });
  ASSERT_EQ(device.position.size(), cpu.position.size());
  EXPECT_EQ(device.position, cpu.position);
  EXPECT_EQ(device.velocity, cpu.velocity);
  std::printf(
      "thrown at the floor, over %ld steps: %d fluid particles found on its surface, %d "
      "below it\n",
      device.steps, on_floor, below);
  EXPECT_GT(on_floor, 0);  // the put-back happened
  EXPECT_EQ(below, 0);
}

TEST(WcsphDevice, GpuRefusedWithTheReasonWhereNoneIsFound) {
  std::string why;
  if (wcsph_device_available(WcsphDevice::kGpu, why)) GTEST_SKIP() << "a GPU is here";
  EXPECT_EQ(exec::gpu_memory().free_bytes, 0);  // unknown: no refusal by size
  try {
    Simulation<2> sim(testing::load_case("dam_break_2d.yaml", {"model.device=gpu"}));
    FAIL() << "a run on the GPU started without one";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("model.device"), std::string::npos) << message;
    EXPECT_NE(message.find(why), std::string::npos) << message;
  }
}

// ---------------------------------------------------------------------------------------------
// On a GPU.

bool gpu_here() {
  std::string why;
  if (wcsph_device_available(WcsphDevice::kGpu, why)) return true;
  std::printf("no GPU: %s\n", why.c_str());
  return false;
}

// The backend's own pieces first (its arrays, a loop, the sort, the scan, the reduction), on a
// few values and on a million: what fails here is the backend, not the model.
TEST(WcsphGpu, BackendAgreesWithTheHost) {
  if (!gpu_here()) GTEST_SKIP() << "no GPU";
#if defined(SLUICE_WITH_CUDA)
  for (const std::size_t n : {std::size_t{1000}, std::size_t{1} << 20})
    EXPECT_EQ(exec::check_cuda_backend(n), "") << n << " values";
#endif
}

// The GPU's free memory, as the size check before a run reads it: a case that needs several
// times of it is refused at its spacing, naming the GPU, before anything is built.
TEST(WcsphGpu, ACaseTooLargeForTheGpusMemoryIsRefusedAtItsSpacing) {
  if (!gpu_here()) GTEST_SKIP() << "no GPU";
  const exec::DeviceMemory gpu = exec::gpu_memory();
  std::printf("%s: %.3g GB free\n", gpu.name.c_str(), gpu.free_bytes / 1e9);
  EXPECT_GT(gpu.free_bytes, 1e9);
  EXPECT_NE(gpu.name.find("(CUDA)"), std::string::npos) << gpu.name;
  io::CaseConfig config = testing::load_case("bench_dam_break_3d.yaml", {"model.device=gpu"});
  ASSERT_TRUE(runs_on_a_gpu(config));
  EXPECT_NO_THROW(refuse_if_the_gpu_cannot_hold(config, estimate_size(config), gpu));
  // The water grows as the spacing to the power -3, the walls as -2: at this spacing the
  // estimate needs more than the free memory (four times, were the walls to grow as the water).
  const double needed =
      estimate_size(config).elements * wcsph_device_bytes_per_particle(config.dimension);
  config.spacing *= std::cbrt(needed / (4 * gpu.free_bytes));
  try {
    refuse_if_the_gpu_cannot_hold(config, estimate_size(config), gpu);
    FAIL() << "not refused at " << config.spacing << " m";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.key(), "spacing") << message;
    EXPECT_NE(message.find(gpu.name), std::string::npos) << message;
  }
}

// F1: the still tank's bottom pressure after 2 s, on the GPU and on the CPU.
double tank_bottom_pressure(const std::vector<std::string>& overrides) {
  Simulation<2> sim(testing::load_case("hydrostatic_2d.yaml", overrides));
  testing::run_until(sim, 2.0, [](const StepClock&) {});
  io::ProbeConfig bottom;
  bottom.kind = io::ProbeKind::kPressure;
  bottom.point = Vec3(0.5, 0, 0);
  return Probes({bottom}, "").measure(sim.fluid().observation())[0];
}

TEST(WcsphGpu, StillTankAgreesWithTheCpu) {
  if (!gpu_here()) GTEST_SKIP() << "no GPU";
  const double rho_g_h = 1000 * 9.81 * 1.0;
  const double cpu = tank_bottom_pressure({});
  const double gpu = tank_bottom_pressure({"model.device=gpu"});
  std::printf("F1 bottom pressure: GPU %.2f Pa, CPU %.2f Pa (%+.4f %% of rho g H apart)\n", gpu,
              cpu, 100 * (gpu - cpu) / rho_g_h);
  EXPECT_NEAR(gpu, rho_g_h, 0.03 * rho_g_h);  // F1's bar
  EXPECT_NEAR(gpu, cpu, 0.002 * rho_g_h);
}

TEST(WcsphGpu, DamBreakFrontAgreesWithTheCpu) {
  if (!gpu_here()) GTEST_SKIP() << "no GPU";
  const double cpu = testing::dam_break_front_rms({});
  const double gpu = testing::dam_break_front_rms({"model.device=gpu"});
  std::printf("F2 front RMS: GPU %.4f m, CPU %.4f m\n", gpu, cpu);
  EXPECT_LT(gpu, 0.30);  // F2's bar
  EXPECT_NEAR(gpu, cpu, 0.01);
}

TEST(WcsphGpu, FloatingBoxDraftAgreesWithTheCpu) {
  if (!gpu_here()) GTEST_SKIP() << "no GPU";
  const auto cpu = testing::floating_box_draft({});
  const auto gpu = testing::floating_box_draft({"model.device=gpu"});
  std::printf("B1 mean draft: GPU %.4f m, CPU %.4f m; drift GPU %.3g mm, CPU %.3g mm\n", gpu.draft,
              cpu.draft, 1e3 * gpu.drift, 1e3 * cpu.drift);
  EXPECT_NEAR(gpu.draft, 0.7, 0.03 * 0.7);  // B1's bars
  EXPECT_LT(gpu.drift, 0.01);
  EXPECT_NEAR(gpu.draft, cpu.draft, 0.002 * 0.7);
}

// The bench case (cases/bench_dam_break_3d.yaml) at a coarser spacing: the surge front and the
// fluid's energy after 0.3 s.
struct BenchEnd {
  double front = 0, kinetic = 0, potential = 0;
};
BenchEnd bench_end(const std::vector<std::string>& device) {
  std::vector<std::string> overrides{"spacing=0.02"};
  overrides.insert(overrides.end(), device.begin(), device.end());
  Simulation<3> sim(testing::load_case("bench_dam_break_3d.yaml", overrides));
  testing::run_until(sim, 0.3, [](const StepClock&) {});
  const FluidEnergy e = sim.fluid().observation().energy();
  return {sim.fluid().observation().surge_front(0), e.kinetic, e.potential};
}

TEST(WcsphGpu, BenchCaseFrontAndEnergyAgreeWithTheCpu) {
  if (!gpu_here()) GTEST_SKIP() << "no GPU";
  const BenchEnd cpu = bench_end({});
  const BenchEnd gpu = bench_end({"model.device=gpu"});
  std::printf(
      "bench case at 0.3 s: front GPU %.4f / CPU %.4f m, kinetic %.3f / %.3f J, "
      "potential %.3f / %.3f J\n",
      gpu.front, cpu.front, gpu.kinetic, cpu.kinetic, gpu.potential, cpu.potential);
  EXPECT_NEAR(gpu.front, cpu.front, 0.02);  // half a spacing
  EXPECT_NEAR(gpu.kinetic, cpu.kinetic, 0.02 * cpu.kinetic);
  EXPECT_NEAR(gpu.potential, cpu.potential, 0.002 * std::abs(cpu.potential));
}

}  // namespace
}  // namespace sluice
