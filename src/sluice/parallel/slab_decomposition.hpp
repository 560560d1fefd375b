// The domain cut into slabs along one axis, one slab a rank (LAMMPS's and GPUSPH's spatial
// decomposition, in its simplest shape): rank r owns the particles whose coordinate along the
// axis lies in [cut r-1, cut r), the first slab open below and the last above, so that every
// particle has an owner wherever it goes.
#pragma once

#include <span>
#include <string>
#include <vector>

namespace sluice {

class SlabDecomposition {
 public:
  SlabDecomposition() = default;  // one slab: everything on rank 0
  // Slabs along `axis` (the particle's coordinate index) between the ascending `cuts`.
  SlabDecomposition(int axis, std::vector<double> cuts);

  int axis() const { return axis_; }
  int ranks() const { return static_cast<int>(cuts_.size()) + 1; }
  const std::vector<double>& cuts() const { return cuts_; }

  // The rank whose slab holds `coordinate` (along the axis).
  int owner(double coordinate) const;
  // Calls fn(rank) for every rank other than `self` whose slab comes within `depth` of
  // `coordinate`: the ranks that need a copy of a particle there as a ghost.
  template <class Fn>
  void for_each_rank_near(double coordinate, double depth, int self, Fn&& fn) const {
    const int first = owner(coordinate - depth), last = owner(coordinate + depth);
    for (int r = first; r <= last; ++r) {
      if (r != self) fn(r);
    }
  }

  // "3 slabs along x, cut at 0.52 and 1.1 m"
  std::string describe() const;

 private:
  int axis_ = 0;
  std::vector<double> cuts_;
};

// `ranks` slabs along `axis` with an equal share of the `weights` of the particles at
// `coordinates` (along the axis) each; no weights: of the particles. Each cut lies halfway
// between the two particles beside it, and a share that ends within a plane of a lattice takes
// the whole plane, so that no particle lies on a cut.
SlabDecomposition balanced_slabs(std::span<const double> coordinates,
                                 std::span<const double> weights, int axis, int ranks);

}  // namespace sluice
