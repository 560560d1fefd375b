#include "sluice/fluid/mac/velocity_extension.hpp"

#include <algorithm>

#include "sluice/exec/policy.hpp"
#include "sluice/fluid/mac/level_set.hpp"

namespace sluice {

template <int D>
std::vector<Real> phi_at_faces(const MacGrid<D>& grid, const CellField& phi, int axis) {
  const Lattice<D> cells = grid.cell_lattice();
  const Lattice<D> faces = grid.face_lattice(axis);
  std::vector<Real> out(faces.size());
  exec::Default::for_each_light(out.size(), [&](std::size_t k) {
    GridIndex<D> c = faces.coordinates(k);
    const int upper = c[axis];
    Real sum = 0;
    int count = 0;
    for (const int cell : {upper - 1, upper}) {
      if (axis != grid.periodic_axis && (cell < 0 || cell >= grid.cells[axis])) continue;
      c[axis] = cell;
      sum += phi[cells.index(c)];
      ++count;
    }
    out[k] = sum / count;
  });
  return out;
}

template <int D>
void extend_velocity(const MacGrid<D>& grid, const CellField& phi, const FaceMarks<D>& known,
                     FaceField<D>& u, Real band) {
  for (int axis = 0; axis < D; ++axis) {
    const Lattice<D> faces = grid.face_lattice(axis);
    const std::vector<Real> level = phi_at_faces(grid, phi, axis);
    std::vector<char> set = known[axis];
    std::vector<Real>& v = u[axis];
    for (int round = 0; round < 2; ++round) {
      for_each_sweep<D>(faces, [&](std::size_t k, const GridIndex<D>& c) {
        if (known[axis][k] || level[k] > band) return;
        Real weight_sum = 0, value_sum = 0, plain_sum = 0;
        int plain_count = 0;
        for (int b = 0; b < D; ++b) {
          // The neighbour along b nearer the water, among those with a value.
          std::size_t best = 0;
          Real best_level = 1e300;
          for (const int side : {-1, 1}) {
            GridIndex<D> n = c;
            n[b] += side;
            if (!faces.contains(n)) continue;
            const std::size_t m = faces.index(n);
            if (!set[m]) continue;
            plain_sum += v[m];
            ++plain_count;
            if (level[m] < best_level) {
              best_level = level[m];
              best = m;
            }
          }
          if (best_level < 1e300) {
            const Real w = std::max(Real(0), level[k] - best_level);
            weight_sum += w;
            value_sum += w * v[best];
          }
        }
        if (weight_sum > 0) {
          v[k] = value_sum / weight_sum;
          set[k] = 1;
        } else if (plain_count > 0) {
          v[k] = plain_sum / plain_count;
          set[k] = 1;
        }
      });
    }
  }
}

template std::vector<Real> phi_at_faces<2>(const MacGrid<2>&, const CellField&, int);
template std::vector<Real> phi_at_faces<3>(const MacGrid<3>&, const CellField&, int);
template void extend_velocity<2>(const MacGrid<2>&, const CellField&, const FaceMarks<2>&,
                                 FaceField<2>&, Real);
template void extend_velocity<3>(const MacGrid<3>&, const CellField&, const FaceMarks<3>&,
                                 FaceField<3>&, Real);

}  // namespace sluice
