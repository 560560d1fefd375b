// Micro-benchmark of the grid model's advection on F3's grid at 0.02 m (161 x 50 x 50 cells):
// sampling the face velocities at points, and one MacCormack step of a face component, the
// two loops that take most of `mac`'s step (docs/performance.md, "Sampling the grid").
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "sluice/fluid/mac/advection.hpp"

namespace {

sluice::MacGrid<3> f3_grid() {
  sluice::MacGrid<3> grid;
  grid.cells = {161, 50, 50};
  grid.h = 0.02;
  return grid;
}

// A smooth swirl of about 1 m/s, so that traces cross cells as in a dam break.
sluice::FaceField<3> swirl(const sluice::MacGrid<3>& grid) {
  sluice::FaceField<3> u = sluice::make_face_field(grid);
  for (int a = 0; a < 3; ++a) {
    const sluice::Lattice<3> faces = grid.face_lattice(a);
    for (std::size_t k = 0; k < u[a].size(); ++k) {
      const sluice::Vec<3> x = faces.position(faces.coordinates(k));
      u[a][k] = std::sin(3 * x[(a + 1) % 3]) * std::cos(2 * x[(a + 2) % 3]);
    }
  }
  return u;
}

void BM_VelocityAt(benchmark::State& state) {
  const sluice::MacGrid<3> grid = f3_grid();
  const sluice::FaceField<3> u = swirl(grid);
  std::mt19937 random(1);
  std::uniform_real_distribution<double> x(0, 3.22), yz(0, 1);
  std::vector<sluice::Vec<3>> points(1 << 20);
  for (auto& p : points) p = sluice::Vec<3>(x(random), yz(random), yz(random));
  for (auto _ : state) {
    double total = 0;
    for (const auto& p : points) total += sluice::velocity_at(grid, u, p)[0];
    benchmark::DoNotOptimize(total);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(points.size()));
}
BENCHMARK(BM_VelocityAt)->Unit(benchmark::kMillisecond);

void BM_AdvectMacCormack(benchmark::State& state) {
  const sluice::MacGrid<3> grid = f3_grid();
  const sluice::FaceField<3> u = swirl(grid);
  const sluice::Lattice<3> faces = grid.face_lattice(0);
  for (auto _ : state) {
    benchmark::DoNotOptimize(sluice::advect_maccormack(faces, u[0], grid, u, 0.005));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(u[0].size()));
}
BENCHMARK(BM_AdvectMacCormack)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
