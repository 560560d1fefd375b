// Principle 13 of DESIGN.md: the same answer on any number of threads, bit for bit.
#include <gtest/gtest.h>
#include <omp.h>

#include <memory>
#include <string>
#include <vector>

#include "particle_state_of.hpp"
#include "physics_support.hpp"

namespace sluice {
namespace {

ParticleSet<2> run_with_threads(int threads) {
  omp_set_num_threads(threads);
  Simulation<2> sim(testing::load_case("dam_break_2d.yaml", {"spacing=0.05"}));
  testing::run_until(sim, 0.05, [](const StepClock&) {});
  return testing::particle_state(sim).particles;
}

TEST(Determinism, DamBreakSameOnOneAndTwoThreads) {
  const int before = omp_get_max_threads();
  const ParticleSet<2> one = run_with_threads(1);
  const ParticleSet<2> two = run_with_threads(2);
  omp_set_num_threads(before);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    ASSERT_EQ(one.position[i], two.position[i]) << "particle " << i;
    ASSERT_EQ(one.velocity[i], two.velocity[i]) << "particle " << i;
    ASSERT_EQ(one.density[i], two.density[i]) << "particle " << i;
  }
}

// The MPS model: neighbour list, assembly and the conjugate gradient's products run on all
// threads, each row summed by one thread.
TEST(Determinism, MpsDamBreakSameOnOneAndTwoThreads) {
  const int before = omp_get_max_threads();
  ParticleSet<2> runs[2];
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    Simulation<2> sim(testing::load_case("dam_break_2d_mps.yaml", {"spacing=0.05"}));
    testing::run_until(sim, 0.1, [](const StepClock&) {});
    runs[threads - 1] = testing::particle_state(sim).particles;
  }
  omp_set_num_threads(before);
  ASSERT_EQ(runs[0].size(), runs[1].size());
  for (std::size_t i = 0; i < runs[0].size(); ++i) {
    ASSERT_EQ(runs[0].position[i], runs[1].position[i]) << "particle " << i;
    ASSERT_EQ(runs[0].velocity[i], runs[1].velocity[i]) << "particle " << i;
    ASSERT_EQ(runs[0].pressure[i], runs[1].pressure[i]) << "particle " << i;
  }
}

// The bodies and particles of two runs, bit for bit; the first run must have taken more than
// `least_substeps` solid sub-steps (the contacts were in play).
template <int D>
void expect_same_runs(const Simulation<D>& one, const Simulation<D>& two, long least_substeps) {
  ASSERT_EQ(one.clock().step, two.clock().step);
  ASSERT_GT(one.bodies().substeps(), least_substeps);
  for (std::size_t b = 0; b < one.bodies().count(); ++b) {
    const RigidBody& a = one.bodies().state(b);
    const RigidBody& c = two.bodies().state(b);
    EXPECT_EQ(a.position, c.position) << "body " << b;
    EXPECT_EQ(a.velocity, c.velocity) << "body " << b;
    EXPECT_EQ(a.orientation.coeffs(), c.orientation.coeffs()) << "body " << b;
    EXPECT_EQ(a.angular_momentum, c.angular_momentum) << "body " << b;
    EXPECT_EQ(one.coupler().fluid_force()[b], two.coupler().fluid_force()[b]) << "body " << b;
    EXPECT_EQ(one.bodies().system().contact_force()[b], two.bodies().system().contact_force()[b]);
  }
  const auto& p1 = testing::particle_state(one).particles;
  const auto& p2 = testing::particle_state(two).particles;
  ASSERT_EQ(p1.size(), p2.size());
  for (std::size_t i = 0; i < p1.size(); ++i) {
    ASSERT_EQ(p1.position[i], p2.position[i]) << "particle " << i;
    ASSERT_EQ(p1.velocity[i], p2.velocity[i]) << "particle " << i;
    ASSERT_EQ(p1.pressure[i], p2.pressure[i]) << "particle " << i;
  }
}

// A case run on a number of threads to `end`.
template <int D>
std::unique_ptr<Simulation<D>> run_on(int threads, const std::string& name,
                                      const std::vector<std::string>& overrides, double end) {
  omp_set_num_threads(threads);
  auto sim = std::make_unique<Simulation<D>>(testing::load_case(name, overrides));
  testing::run_until(*sim, end, [](const StepClock&) {});
  return sim;
}

// Bodies too: the contact, the sub-cycling and the fluid's loads on them are summed in one
// thread's order, whatever the number of threads. Two blocks sinking in water until both have
// landed (coarse, to keep it short).
TEST(Determinism, BodiesInWaterSameOnOneAndTwoThreads) {
  const int before = omp_get_max_threads();
  const auto one = run_on<2>(1, "subcycling_2d.yaml", {"spacing=0.02"}, 0.45);
  const auto two = run_on<2>(2, "subcycling_2d.yaml", {"spacing=0.02"}, 0.45);
  omp_set_num_threads(before);
  expect_same_runs(*one, *two, one->clock().step);  // the blocks did land
}

// In 3D with bodies in contact from the start: three cubes stacked on the floor of the
// dam-break tank (coarse and short: the contacts sub-cycle every step).
TEST(Determinism, StackedCubesIn3DSameOnOneAndTwoThreads) {
  const int before = omp_get_max_threads();
  const auto one = run_on<3>(1, "dam_break_cubes_3.yaml", {"spacing=0.05"}, 0.03);
  const auto two = run_on<3>(2, "dam_break_cubes_3.yaml", {"spacing=0.05"}, 0.03);
  omp_set_num_threads(before);
  expect_same_runs(*one, *two, 2 * one->clock().step);
}

// Free grains under water (penalty-sph): the fluid's reaction on each grain is summed in
// particle order over many exchanges a step.
TEST(Determinism, FreeGrainBedSameOnOneAndTwoThreads) {
  const int before = omp_get_max_threads();
  const auto one = run_on<2>(1, "free_bed_2d.yaml", {}, 0.3);
  const auto two = run_on<2>(2, "free_bed_2d.yaml", {}, 0.3);
  omp_set_num_threads(before);
  expect_same_runs(*one, *two, one->clock().step);
}

}  // namespace
}  // namespace sluice
