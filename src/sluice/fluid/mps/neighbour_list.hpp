// Each particle's neighbours within a radius, found once per step right after the neighbour
// sort and kept in one array, rows in particle order: every operator of an MPS step reads
// them instead of scanning the cells again. Built in two parallel passes (count, then fill),
// each row by one thread, so the list is the same on any number of threads.
#pragma once

#include <cstdint>
#include <vector>

#include "sluice/exec/policy.hpp"
#include "sluice/neighbor/cell_list.hpp"

namespace sluice {

template <int D>
class NeighbourList {
 public:
  // Rows for the particles where wanted(i) holds (the others get empty rows): every j != i
  // with |r_i - r_j| < radius. `radius` must not exceed the cells' radius.
  template <class Wanted>
  void build(const std::vector<Vec<D>>& positions, const CellList<D>& cells, Real radius,
             Wanted&& wanted) {
    const std::size_t n = positions.size();
    const Real radius2 = radius * radius;
    start_.assign(n + 1, 0);
    exec::Default::for_each_balanced(n, [&](std::size_t i) {
      if (!wanted(i)) return;
      std::uint32_t count = 0;
      cells.for_each_neighbor(positions, i, radius2,
                              [&](std::size_t, const Vec<D>&, Real) { ++count; });
      start_[i + 1] = count;
    });
    for (std::size_t i = 0; i < n; ++i) start_[i + 1] += start_[i];
    index_.resize(start_[n]);
    exec::Default::for_each_balanced(n, [&](std::size_t i) {
      if (!wanted(i)) return;
      std::uint32_t k = start_[i];
      cells.for_each_neighbor(positions, i, radius2, [&](std::size_t j, const Vec<D>&, Real) {
        index_[k++] = static_cast<std::uint32_t>(j);
      });
    });
  }

  std::size_t size() const { return start_.empty() ? 0 : start_.size() - 1; }
  std::size_t entries() const { return index_.size(); }

  // fn(j) for each neighbour j of i, in increasing index.
  template <class Fn>
  void for_each(std::size_t i, Fn&& fn) const {
    for (std::uint32_t k = start_[i]; k < start_[i + 1]; ++k)
      fn(static_cast<std::size_t>(index_[k]));
  }

 private:
  std::vector<std::uint32_t> start_;
  std::vector<std::uint32_t> index_;
};

}  // namespace sluice
