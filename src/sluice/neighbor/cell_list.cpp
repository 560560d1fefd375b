#include "sluice/neighbor/cell_list.hpp"

#include <cmath>
#include <stdexcept>

#include "sluice/exec/policy.hpp"

namespace sluice {

template <int D>
CellGridView<D> cell_grid_over(const Vec<D>& lo, const Vec<D>& hi, Real radius,
                               std::size_t& cells) {
  CellGridView<D> grid;
  grid.cell_size = radius;
  grid.inverse_cell_size = 1 / radius;
  std::size_t total = 1;
  for (int a = 0; a < D; ++a) {
    grid.lo[a] = lo[a];
    grid.counts[a] = static_cast<int>(std::ceil((hi[a] - lo[a]) * grid.inverse_cell_size)) + 1 +
                     2 * CellGridView<D>::kReach;
    total *= static_cast<std::size_t>(grid.counts[a]);
  }
  if (total > (std::size_t{1} << 31)) {
    throw std::runtime_error("the domain holds too many neighbour cells; enlarge the spacing");
  }
  cells = total;
  return grid;
}

template <int D>
CellList<D>::CellList(const Vec<D>& lo, const Vec<D>& hi, Real radius) {
  std::size_t cells = 0;
  grid_ = cell_grid_over<D>(lo, hi, radius, cells);
  cell_start_.assign(cells + 1, 0);
}

template <int D>
void CellList<D>::sort(const std::vector<Vec<D>>& positions, std::vector<std::uint32_t>& order,
                       const std::vector<bool>* gone) {
  const std::size_t n = positions.size();
  cell_of_.resize(n);
  exec::Default::for_each(n,
                          [&](std::size_t i) { cell_of_[i] = grid_.cell_of(positions[i].data()); });
  const auto kept = [&](std::size_t i) { return gone == nullptr || !(*gone)[i]; };
  // Counting sort: stable, so particles keep their relative order within a cell and the
  // result does not depend on the thread count.
  std::fill(cell_start_.begin(), cell_start_.end(), 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (kept(i)) ++cell_start_[cell_of_[i] + 1];
  }
  for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  order.resize(cell_start_.back());
  std::vector<std::uint32_t> next(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i) {
    if (kept(i)) order[next[cell_of_[i]]++] = static_cast<std::uint32_t>(i);
  }
}

template CellGridView<2> cell_grid_over(const Vec<2>&, const Vec<2>&, Real, std::size_t&);
template CellGridView<3> cell_grid_over(const Vec<3>&, const Vec<3>&, Real, std::size_t&);
template class CellList<2>;
template class CellList<3>;

}  // namespace sluice
