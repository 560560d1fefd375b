#include "sluice/parallel/slab_decomposition.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace sluice {

SlabDecomposition::SlabDecomposition(int axis, std::vector<double> cuts)
    : axis_(axis), cuts_(std::move(cuts)) {
  if (!std::is_sorted(cuts_.begin(), cuts_.end()))
    throw std::logic_error("SlabDecomposition: the cuts must ascend");
}

int SlabDecomposition::owner(double coordinate) const {
  return static_cast<int>(std::upper_bound(cuts_.begin(), cuts_.end(), coordinate) - cuts_.begin());
}

std::string SlabDecomposition::describe() const {
  const char* axis_name = axis_ == 0 ? "x" : axis_ == 1 ? "y" : "z";
  if (cuts_.empty()) return "one slab";
  return fmt::format("{} slabs along {}, cut at {:.4g} m", ranks(), axis_name,
                     fmt::join(cuts_, ", "));
}

SlabDecomposition balanced_slabs(std::span<const double> coordinates,
                                 std::span<const double> weights, int axis, int ranks) {
  if (ranks < 1) throw std::logic_error("balanced_slabs: at least one rank");
  if (!weights.empty() && weights.size() != coordinates.size())
    throw std::logic_error("balanced_slabs: one weight a coordinate");
  std::vector<std::pair<double, double>> sorted;  // coordinate, weight
  for (std::size_t i = 0; i < coordinates.size(); ++i)
    sorted.emplace_back(coordinates[i], weights.empty() ? 1.0 : weights[i]);
  std::sort(sorted.begin(), sorted.end());
  double total = 0;
  for (const auto& p : sorted) total += p.second;
  std::vector<double> cuts;
  const std::size_t n = sorted.size();
  std::size_t above = 0;  // the first particle of the slab above the cut
  double below = 0;       // the weight under it
  for (int r = 1; r < ranks; ++r) {
    const double share = total * r / ranks;
    while (above < n && below + sorted[above].second <= share) below += sorted[above++].second;
    // Between the last particle of the slab below and the first above; a lattice puts many on
    // one coordinate, so move up to where the coordinate changes.
    while (above > 0 && above < n && sorted[above].first == sorted[above - 1].first)
      below += sorted[above++].second;
    const double cut = n == 0       ? 0.0
                       : above == 0 ? sorted[0].first
                       : above == n ? sorted[n - 1].first
                                    : 0.5 * (sorted[above - 1].first + sorted[above].first);
    cuts.push_back(cuts.empty() ? cut : std::max(cut, cuts.back()));
  }
  return SlabDecomposition(axis, std::move(cuts));
}

}  // namespace sluice
