// Each particle's neighbours within a radius, found once per step right after the neighbour
// sort and kept in one array, rows in particle order: every operator of an MPS step reads
// them instead of scanning the cells again. Built in one scan of the cells: blocks of rows,
// each filled by one thread into a buffer of its own (kept from step to step), then copied
// into place; so the list is the same on any number of threads.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "sluice/exec/policy.hpp"
#include "sluice/fluid/mps/neighbour_view.hpp"
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
    const std::size_t blocks = (n + kBlock - 1) / kBlock;
    if (buffers_.size() < blocks) buffers_.resize(blocks);
    start_.assign(n + 1, 0);
    const CellGridView<D> grid = cells.view();
    exec::Default::for_each_balanced(blocks, [&](std::size_t b) {
      std::vector<std::uint32_t>& buffer = buffers_[b];
      buffer.clear();
      for (std::size_t i = b * kBlock; i < std::min(n, (b + 1) * kBlock); ++i) {
        if (!wanted(i)) continue;
        const std::size_t before = buffer.size();
        for_each_neighbour_within(grid, positions.data(), i, radius2,
                                  [&](std::uint32_t j) { buffer.push_back(j); });
        start_[i + 1] = static_cast<std::uint32_t>(buffer.size() - before);
      }
    });
    for (std::size_t i = 0; i < n; ++i) start_[i + 1] += start_[i];
    index_.resize(start_[n]);
    exec::Default::for_each(blocks, [&](std::size_t b) {
      std::copy(buffers_[b].begin(), buffers_[b].end(), index_.begin() + start_[b * kBlock]);
    });
  }

  std::size_t size() const { return start_.empty() ? 0 : start_.size() - 1; }
  std::size_t entries() const { return index_.size(); }

  // fn(j) for each neighbour j of i, in increasing index.
  template <class Fn>
  void for_each(std::size_t i, Fn&& fn) const {
    view().for_each(i, fn);
  }
  NeighbourView view() const { return {start_.data(), index_.data()}; }

  // The rows' starts (one more than the rows) and the neighbours, as plain arrays; and a list
  // made of them (a device's, copied back).
  const std::vector<std::uint32_t>& starts() const { return start_; }
  const std::vector<std::uint32_t>& indices() const { return index_; }
  void assign(std::vector<std::uint32_t> start, std::vector<std::uint32_t> index) {
    start_ = std::move(start);
    index_ = std::move(index);
  }

  // Checkpoints: the list is built at the predicted positions, which the particles have left.
  void archive_state(StateArchive& a) { a(start_, index_); }

 private:
  std::vector<std::uint32_t> start_;
  std::vector<std::uint32_t> index_;
  static constexpr std::size_t kBlock = 256;  // rows per buffer
  std::vector<std::vector<std::uint32_t>> buffers_;
};

}  // namespace sluice
