// Micro-benchmark of the neighbour search: sorting by cell and a full gather of neighbours
// on a 3D lattice at the benchmark case's spacing and smoothing length.
#include <benchmark/benchmark.h>

#include "sluice/neighbor/cell_list.hpp"
#include "sluice/particles/particle_set.hpp"

namespace {

sluice::ParticleSet<3> lattice(int n, double dx) {
  sluice::ParticleSet<3> ps;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        ps.add(sluice::Vec<3>(i * dx, j * dx, k * dx), sluice::Vec<3>::Zero(), 1000, 1,
               sluice::ParticleKind::kFluid);
  return ps;
}

void BM_SortByCell(benchmark::State& state) {
  const double dx = 0.0085, radius = 2.6 * dx;
  auto ps = lattice(static_cast<int>(state.range(0)), dx);
  sluice::CellList<3> cells(sluice::Vec<3>::Zero(), sluice::Vec<3>::Constant(state.range(0) * dx),
                            radius);
  std::vector<std::uint32_t> order;
  for (auto _ : state) {
    cells.sort(ps.position, order);
    ps.reorder(order);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(ps.size()));
}
BENCHMARK(BM_SortByCell)->Arg(40)->Unit(benchmark::kMillisecond);

void BM_GatherNeighbours(benchmark::State& state) {
  const double dx = 0.0085, radius = 2.6 * dx;
  auto ps = lattice(static_cast<int>(state.range(0)), dx);
  sluice::CellList<3> cells(sluice::Vec<3>::Zero(), sluice::Vec<3>::Constant(state.range(0) * dx),
                            radius);
  std::vector<std::uint32_t> order;
  cells.sort(ps.position, order);
  ps.reorder(order);
  for (auto _ : state) {
    double total = 0;
    for (std::size_t i = 0; i < ps.size(); ++i) {
      cells.for_each_neighbor(ps.position, i, radius * radius,
                              [&](std::size_t, const sluice::Vec<3>&, double r2) { total += r2; });
    }
    benchmark::DoNotOptimize(total);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(ps.size()));
}
BENCHMARK(BM_GatherNeighbours)->Arg(40)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
