#include "sluice/rigid/body_islands.hpp"

#include <algorithm>
#include <numeric>

namespace sluice {

namespace {

std::size_t root(std::vector<std::size_t>& parent, std::size_t b) {
  while (parent[b] != b) b = parent[b] = parent[parent[b]];  // path halving
  return b;
}

}  // namespace

std::vector<int> body_islands(const std::vector<bool>& fixed, const std::vector<IslandPair>& pairs,
                              const std::vector<IslandPair>& links) {
  const std::size_t n = fixed.size();
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto tie = [&](const IslandPair& p) {
    if (p.first >= n || p.second >= n || fixed[p.first] || fixed[p.second]) return;
    const std::size_t a = root(parent, p.first), b = root(parent, p.second);
    parent[std::max(a, b)] = std::min(a, b);  // the lowest body is the root
  };
  for (const IslandPair& p : pairs) tie(p);
  for (const IslandPair& p : links) tie(p);
  std::vector<int> island(n, -1), of_root(n, -1);
  int count = 0;
  for (std::size_t b = 0; b < n; ++b) {
    if (fixed[b]) continue;
    const std::size_t r = root(parent, b);
    if (of_root[r] < 0) of_root[r] = count++;
    island[b] = of_root[r];
  }
  return island;
}

std::vector<int> island_ranks(const std::vector<double>& work, int ranks) {
  std::vector<std::size_t> order(work.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return work[i] > work[j]; });
  std::vector<double> load(static_cast<std::size_t>(std::max(ranks, 1)), 0.0);
  std::vector<int> rank(work.size(), 0);
  for (const std::size_t i : order) {
    const auto least = std::min_element(load.begin(), load.end());
    rank[i] = static_cast<int>(least - load.begin());
    *least += work[i];
  }
  return rank;
}

}  // namespace sluice
