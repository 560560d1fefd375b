#include "sluice/parallel/decomposition.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace sluice {

Decomposition::Decomposition(int dimension, std::vector<RankBox> boxes)
    : dimension_(dimension), boxes_(std::move(boxes)) {
  if (dimension_ < 1 || dimension_ > 3) throw std::logic_error("Decomposition: 1 to 3 axes");
  if (boxes_.empty()) throw std::logic_error("Decomposition: a box a rank, at least one");
}

std::string Decomposition::describe() const {
  if (is_slabs()) return slabs_.describe();
  return fmt::format("{} boxes by recursive coordinate bisection (Zoltan RCB)", boxes_.size());
}

std::vector<double> Decomposition::regions() const {
  if (is_slabs()) return slabs_.cuts();
  std::vector<double> out;
  for (const RankBox& b : boxes_) {
    for (int a = 0; a < dimension_; ++a) out.push_back(b.lo[a]);
    for (int a = 0; a < dimension_; ++a) out.push_back(b.hi[a]);
  }
  return out;
}

Decomposition Decomposition::with_regions(const std::vector<double>& regions) const {
  if (is_slabs()) return Decomposition(SlabDecomposition(slabs_.axis(), regions));
  const std::size_t per_box = 2 * static_cast<std::size_t>(dimension_);
  if (regions.size() % per_box != 0 || regions.empty())
    throw std::runtime_error("a checkpoint's rank boxes are not whole boxes");
  std::vector<RankBox> boxes(regions.size() / per_box);
  for (std::size_t r = 0; r < boxes.size(); ++r) {
    for (int a = 0; a < dimension_; ++a) {
      boxes[r].lo[a] = regions[r * per_box + a];
      boxes[r].hi[a] = regions[r * per_box + dimension_ + a];
    }
  }
  return Decomposition(dimension_, std::move(boxes));
}

}  // namespace sluice
