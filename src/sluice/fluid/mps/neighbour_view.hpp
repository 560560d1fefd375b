// An MPS neighbour list as loop bodies on the host or a device read it, and the search that
// fills one (neighbour_list.hpp builds the host's; mps_device_run_impl.hpp a device's).
#pragma once

#include <cmath>
#include <cstdint>

#include "sluice/core/host_device.hpp"
#include "sluice/core/types.hpp"
#include "sluice/neighbor/cell_list.hpp"

namespace sluice {

// A neighbour list as plain arrays, for loop bodies on the host or a device: row i's
// neighbours are index[start[i]] ... index[start[i + 1] - 1], in increasing index.
struct NeighbourView {
  const std::uint32_t* start = nullptr;
  const std::uint32_t* index = nullptr;

  template <class Fn>
  SLUICE_HOST_DEVICE void for_each(std::size_t i, Fn&& fn) const {
    for (std::uint32_t k = start[i]; k < start[i + 1]; ++k) fn(static_cast<std::size_t>(index[k]));
  }
};

// Calls fn(j) for every particle j != i within sqrt(radius2) of particle i, in increasing index
// (the cells' candidate ranges in order). Where the processor fuses multiplies and adds, r^2 has
// them fused by hand, so that every build of a list (the host's, a device's count and its fill)
// finds the same neighbours whatever the compiler would fuse around it; where it does not (the
// baseline x86-64-v2 build), nothing can be fused, and a fused multiply-add would be a library
// call per candidate.
template <int D, class Fn>
SLUICE_HOST_DEVICE void for_each_neighbour_within(const CellGridView<D>& cells, const Vec<D>* x,
                                                  std::size_t i, Real radius2, Fn&& fn) {
  const Real* xi = x[i].data();
  cells.for_each_candidate_range(xi, [&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t j = begin; j < end; ++j) {
      if (j == i) continue;
      const Real* xj = x[j].data();
      Real r2 = 0;
      for (int a = 0; a < D; ++a) {
        const Real d = xi[a] - xj[a];
#if defined(__FMA__) || defined(__CUDA_ARCH__)
        r2 = std::fma(d, d, r2);
#else
        r2 += d * d;
#endif
      }
      if (r2 < radius2) fn(j);
    }
  });
}

}  // namespace sluice
