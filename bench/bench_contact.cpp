// Solid sub-cycling against the solid step everywhere (VALIDATION.md C6): a ball bouncing on a
// floor for 1 s of simulated time, stepped at 1 ms by the caller.
#include <benchmark/benchmark.h>

#include "sluice/contact/contact_body_builder.hpp"
#include "sluice/contact/multibody_system.hpp"

namespace {

using sluice::Vec3;

sluice::MultibodySystem bouncing_ball() {
  const sluice::ContactMaterial material{1e8, 0.3, 0.9, 0.3};
  const double dx = 0.01, radius = 0.1;
  sluice::MultibodySystem system(dx, Vec3(0, 0, -9.81));
  system.add(sluice::make_floor_patch(0.2, dx, material));
  sluice::ContactBody ball = sluice::make_contact_body(sluice::sample_sphere_body(radius, dx, 0, 3),
                                                       sluice::sphere_mass_properties(radius, 1000),
                                                       material, radius, false);
  ball.spherical = true;
  ball.state.position = Vec3(0, 0, radius + 0.1);
  system.add(ball);
  return system;
}

void BM_BouncingBallSubCycled(benchmark::State& state) {
  for (auto _ : state) {
    sluice::MultibodySystem system = bouncing_ball();
    for (int step = 0; step < 1000; ++step) system.advance(1e-3);
    state.counters["solid_steps"] = static_cast<double>(system.substeps_taken());
  }
}
BENCHMARK(BM_BouncingBallSubCycled)->Unit(benchmark::kMillisecond);

void BM_BouncingBallSolidStepEverywhere(benchmark::State& state) {
  // The sub-step the impacts need (7 per 1 ms step, as the sub-cycled run takes at impact).
  const int inner = 7;
  for (auto _ : state) {
    sluice::MultibodySystem system = bouncing_ball();
    for (int step = 0; step < 1000 * inner; ++step) system.advance(1e-3 / inner);
    state.counters["solid_steps"] = static_cast<double>(system.substeps_taken());
  }
}
BENCHMARK(BM_BouncingBallSolidStepEverywhere)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
