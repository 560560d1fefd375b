#include "sluice/fluid/mac/volume_correction.hpp"

#include <algorithm>
#include <cmath>

#include "sluice/exec/policy.hpp"

namespace sluice {

namespace {
// Newton's iterations at most: the volume is linear in the shift until a cell leaves or joins
// the interface band, so two are usually exact.
constexpr int kNewtonIterations = 4;
constexpr Real kLargestShift = 0.25;  // [cells]
}  // namespace

template <int D>
bool opens_to_air(const SolidFaces<D>& solid, int a, std::size_t f) {
  const bool outlet = !solid.outlet_pressure[a].empty() && !std::isnan(solid.outlet_pressure[a][f]);
  return solid.open[a][f] > 0 && !outlet;
}

template <int D>
double water_volume_of(const MacGrid<D>& grid, const CellField& phi,
                       const std::vector<char>& excluded) {
  const Real cell_volume = std::pow(grid.h, D);
  return exec::Default::sum_of(phi.size(), [&](std::size_t k) {
    return excluded[k] ? 0.0 : water_fraction(phi[k], grid.h) * cell_volume;
  });
}

template <int D>
double boundary_inflow(const MacGrid<D>& grid, const FaceField<D>& u, const CellField& phi,
                       const SolidFaces<D>& solid, Real dt) {
  const Real area = std::pow(grid.h, D - 1);
  double inflow = 0;
  for_each_boundary_face(grid, [&](int a, int side, std::size_t k, std::size_t f) {
    // A closed face (a wall; an inlet) moves at its solid's velocity whatever the extension
    // left in `u` there.
    const Real normal = solid.open[a][f] > 0 ? u[a][f] : solid.velocity[a][f];
    const Real inward = side == 0 ? normal : -normal;
    if (inward > 0 && opens_to_air(solid, a, f)) return;
    inflow += inward * water_fraction(phi[k], grid.h) * area * dt;
  });
  return inflow;
}

template <int D>
VolumeShift shift_to_volume(const MacGrid<D>& grid, CellField& phi,
                            const std::vector<char>& excluded, double volume) {
  const Real h = grid.h;
  const Real cell_volume = std::pow(h, D);
  const double start = water_volume_of(grid, phi, excluded);
  double now = start;
  Real shift = 0;
  const double tolerance = 1e-12 * std::max(volume, double(cell_volume));
  for (int i = 0; i < kNewtonIterations && std::abs(now - volume) > tolerance; ++i) {
    // d(volume)/d(shift): each cell within the smeared band loses cell_volume / h per unit.
    const double band = exec::Default::sum_of(phi.size(), [&](std::size_t k) {
      return !excluded[k] && std::abs(phi[k]) < 0.5 * h ? 1.0 : 0.0;
    });
    if (band == 0) break;
    const Real step = std::clamp<Real>((now - volume) * h / (band * cell_volume),
                                       -kLargestShift * h - shift, kLargestShift * h - shift);
    if (step == 0) break;
    exec::Default::for_each_light(phi.size(), [&](std::size_t k) { phi[k] += step; });
    shift += step;
    now = water_volume_of(grid, phi, excluded);
  }
  return {shift, now - start};
}

template bool opens_to_air<2>(const SolidFaces<2>&, int, std::size_t);
template bool opens_to_air<3>(const SolidFaces<3>&, int, std::size_t);
template double water_volume_of<2>(const MacGrid<2>&, const CellField&, const std::vector<char>&);
template double water_volume_of<3>(const MacGrid<3>&, const CellField&, const std::vector<char>&);
template double boundary_inflow<2>(const MacGrid<2>&, const FaceField<2>&, const CellField&,
                                   const SolidFaces<2>&, Real);
template double boundary_inflow<3>(const MacGrid<3>&, const FaceField<3>&, const CellField&,
                                   const SolidFaces<3>&, Real);
template VolumeShift shift_to_volume<2>(const MacGrid<2>&, CellField&, const std::vector<char>&,
                                        double);
template VolumeShift shift_to_volume<3>(const MacGrid<3>&, CellField&, const std::vector<char>&,
                                        double);

}  // namespace sluice
