#include "sluice/contact/broad_phase.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace sluice {

namespace {

constexpr std::int64_t kAxisCells = std::int64_t(1) << 21;  // cells per axis in a key

std::array<std::int64_t, 3> cell_of(const Vec3& p, double cell) {
  return {static_cast<std::int64_t>(std::floor(p[0] / cell)),
          static_cast<std::int64_t>(std::floor(p[1] / cell)),
          static_cast<std::int64_t>(std::floor(p[2] / cell))};
}

std::uint64_t key(std::int64_t i, std::int64_t j, std::int64_t k) {
  auto wrap = [](std::int64_t c) { return static_cast<std::uint64_t>(c + kAxisCells / 2); };
  return (wrap(i) * kAxisCells + wrap(j)) * kAxisCells + wrap(k);
}

double extent(const AxisBox& box) {
  return (box.max - box.min).maxCoeff();
}

}  // namespace

void BroadPhase::find(const std::vector<AxisBox>& boxes, const std::vector<bool>& fixed,
                      const std::vector<bool>& large, double margin, std::vector<BodyPair>& pairs) {
  pairs.clear();
  const std::size_t n = boxes.size();
  if (n < 2) return;
  const double half = 0.5 * margin;
  auto grown = [&](std::uint32_t b) {
    AxisBox box = boxes[b];
    box.min.array() -= half;
    box.max.array() += half;
    return box;
  };
  auto consider = [&](std::uint32_t a, std::uint32_t b) {
    if (fixed[a] && fixed[b]) return;
    if (!boxes[a].overlaps(boxes[b], margin)) return;
    pairs.emplace_back(std::min(a, b), std::max(a, b));
  };

  std::vector<double> extents(n);
  for (std::size_t b = 0; b < n; ++b) extents[b] = extent(boxes[b]);
  std::vector<double> sorted = extents;
  std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
  const double median = sorted[n / 2];
  std::vector<bool> is_large(n);
  large_.clear();
  ordinary_.clear();
  for (std::uint32_t b = 0; b < n; ++b) {
    if (!(boxes[b].min.array() <= boxes[b].max.array()).all()) continue;  // no particles
    is_large[b] = large[b] || extents[b] > 4 * median;
    (is_large[b] ? large_ : ordinary_).push_back(b);
  }

  // Ordinary bodies: every cell a grown box touches lists it; a pair is reported by the one
  // cell that holds the lower corner of the two grown boxes' intersection.
  double cell = 0;
  for (std::uint32_t b : ordinary_) cell = std::max(cell, extents[b] + margin);
  if (!(cell > 0)) cell = 1;
  entries_.clear();
  for (std::uint32_t b : ordinary_) {
    const AxisBox box = grown(b);
    const auto lo = cell_of(box.min, cell), hi = cell_of(box.max, cell);
    for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
      for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
        for (std::int64_t k = lo[2]; k <= hi[2]; ++k) entries_.push_back({key(i, j, k), b});
  }
  std::sort(entries_.begin(), entries_.end(), [](const Entry& x, const Entry& y) {
    return x.cell != y.cell ? x.cell < y.cell : x.body < y.body;
  });
  for (std::size_t first = 0; first < entries_.size();) {
    std::size_t last = first;
    while (last < entries_.size() && entries_[last].cell == entries_[first].cell) ++last;
    for (std::size_t p = first; p < last; ++p) {
      for (std::size_t q = p + 1; q < last; ++q) {
        const std::uint32_t a = entries_[p].body, b = entries_[q].body;
        const Vec3 corner = grown(a).min.cwiseMax(grown(b).min);
        const auto c = cell_of(corner, cell);
        if (key(c[0], c[1], c[2]) == entries_[first].cell) consider(a, b);
      }
    }
    first = last;
  }

  // Large bodies against every other; two large ones once.
  for (std::uint32_t l : large_) {
    for (std::uint32_t b = 0; b < n; ++b) {
      if (b == l || (is_large[b] && b < l)) continue;
      if (!(boxes[b].min.array() <= boxes[b].max.array()).all()) continue;
      consider(l, b);
    }
  }
  std::sort(pairs.begin(), pairs.end());
}

}  // namespace sluice
