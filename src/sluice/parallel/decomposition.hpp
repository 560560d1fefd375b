// The regions the ranks own, in one of two shapes: slabs along one axis (SlabDecomposition;
// shift balancing moves their cuts), or one axis-aligned box a rank, as recursive coordinate
// bisection draws them (Zoltan's RCB, rcb_partition.hpp), whose boxes tile all of space. Either
// way every point has one owner (a region holds its lower faces, not its upper ones) and the
// ranks near a point are those whose region comes within a depth of it.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "sluice/parallel/slab_decomposition.hpp"

namespace sluice {

// A rank's box: [lo, hi) along each axis; an open side lies at +-infinity.
struct RankBox {
  std::array<double, 3> lo{}, hi{};
};

class Decomposition {
 public:
  Decomposition() = default;  // one slab: everything on rank 0
  explicit Decomposition(SlabDecomposition slabs) : slabs_(std::move(slabs)) {}
  // Boxes in `dimension` axes, box r rank r's.
  Decomposition(int dimension, std::vector<RankBox> boxes);

  bool is_slabs() const { return boxes_.empty(); }
  const SlabDecomposition& slabs() const { return slabs_; }
  const std::vector<RankBox>& boxes() const { return boxes_; }
  int ranks() const { return is_slabs() ? slabs_.ranks() : static_cast<int>(boxes_.size()); }

  // The rank whose region holds the point (its first `dimension` coordinates).
  template <class Point>
  int owner(const Point& x) const {
    if (is_slabs()) return slabs_.owner(x[slabs_.axis()]);
    for (std::size_t r = 0; r < boxes_.size(); ++r) {
      if (holds(boxes_[r], x)) return static_cast<int>(r);
    }
    return 0;  // not reached: the boxes tile space (a NaN coordinate, which the check stops)
  }
  // Calls fn(rank) for every rank other than `self` whose region comes within `depth` of the
  // point: the ranks that need a copy of a particle there as a ghost.
  template <class Point, class Fn>
  void for_each_rank_near(const Point& x, double depth, int self, Fn&& fn) const {
    if (is_slabs()) return slabs_.for_each_rank_near(x[slabs_.axis()], depth, self, fn);
    for (std::size_t r = 0; r < boxes_.size(); ++r) {
      if (static_cast<int>(r) != self && within(boxes_[r], x, depth)) fn(static_cast<int>(r));
    }
  }

  // "3 slabs along x, cut at 0.52 and 1.1 m", "4 boxes by recursive bisection (Zoltan RCB)"
  std::string describe() const;

  // As a checkpoint keeps it: the cuts, or each box's lower then upper corner.
  std::vector<double> regions() const;
  // The same shape with the regions read back.
  Decomposition with_regions(const std::vector<double>& regions) const;

 private:
  template <class Point>
  bool holds(const RankBox& b, const Point& x) const {
    for (int a = 0; a < dimension_; ++a) {
      if (!(x[a] >= b.lo[a] && x[a] < b.hi[a])) return false;
    }
    return true;
  }
  template <class Point>
  bool within(const RankBox& b, const Point& x, double depth) const {
    for (int a = 0; a < dimension_; ++a) {
      if (x[a] + depth < b.lo[a] || x[a] - depth >= b.hi[a]) return false;
    }
    return true;
  }

  SlabDecomposition slabs_;
  int dimension_ = 0;
  std::vector<RankBox> boxes_;
};

}  // namespace sluice
