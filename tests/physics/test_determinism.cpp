// Principle 13 of DESIGN.md: the same answer on any number of threads, bit for bit.
#include <gtest/gtest.h>
#include <omp.h>

#include "physics_support.hpp"

namespace sluice {
namespace {

ParticleSet<2> run_with_threads(int threads) {
  omp_set_num_threads(threads);
  Simulation<2> sim(testing::load_case("dam_break_2d.yaml", {"spacing=0.05"}));
  testing::run_until(sim, 0.05, [](const SimulationState<2>&) {});
  return sim.state().particles;
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

}  // namespace
}  // namespace sluice
