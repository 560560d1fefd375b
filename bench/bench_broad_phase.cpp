// Micro-benchmark of the contact broad phase: debris boxes of mixed sizes (1-8 cm) at a fixed
// packing density (one body per 10 cm cube of space) in a tank with six large sides, from a
// thousand to a million bodies. The time per body should stay about flat.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "sluice/contact/broad_phase.hpp"

namespace {

void BM_BroadPhase(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const double side = 0.1 * std::cbrt(static_cast<double>(n));  // the tank's width
  std::mt19937 random(5);
  std::uniform_real_distribution<double> where(0.0, side), size(0.01, 0.08);
  std::vector<sluice::AxisBox> boxes;
  std::vector<bool> fixed, large;
  for (std::size_t k = 0; k < n; ++k) {
    const sluice::Vec3 lo(where(random), where(random), where(random));
    boxes.push_back({lo, lo + sluice::Vec3(size(random), size(random), size(random))});
    fixed.push_back(false);
    large.push_back(false);
  }
  for (int s = 0; s < 6; ++s) {
    sluice::AxisBox wall{sluice::Vec3::Zero(), sluice::Vec3::Constant(side)};
    (s % 2 ? wall.min : wall.max)[s / 2] = (s % 2 ? wall.max : wall.min)[s / 2];
    boxes.push_back(wall);
    fixed.push_back(true);
    large.push_back(true);
  }
  sluice::BroadPhase broad;
  std::vector<sluice::BodyPair> pairs;
  for (auto _ : state) {
    broad.find(boxes, fixed, large, 0.01, pairs);
    benchmark::DoNotOptimize(pairs.data());
  }
  state.counters["pairs"] = static_cast<double>(pairs.size());
  state.SetItemsProcessed(state.iterations() * static_cast<long>(n));
}
BENCHMARK(BM_BroadPhase)->RangeMultiplier(10)->Range(1000, 1000000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
