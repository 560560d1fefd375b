#include "sluice/fluid/mac/open_boundaries.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sluice {

template <int D>
OpenBoundaries<D>::OpenBoundaries(const MacGrid<D>& grid, std::vector<io::BoundaryConfig> sides,
                                  Real density, Real gravity, Real domain_floor)
    : grid_(grid),
      sides_(std::move(sides)),
      density_(density),
      gravity_(gravity),
      floor_(domain_floor) {
  for (const io::BoundaryConfig& side : sides_) {
    const int a = grid_axis(side);
    Layers layers;
    layers.faces = in_layer(grid_.face_lattice(a), a, side.upper ? grid_.cells[a] : 0);
    if (side.kind == io::BoundaryKind::kInlet) {
      const int layer = side.upper ? grid_.cells[a] - 1 : 0;
      layers.cells = in_layer(grid_.cell_lattice(), a, layer);
      for (int b = 0; b < D; ++b)
        if (b != a) layers.across[b] = in_layer(grid_.face_lattice(b), a, layer);
    }
    layers_.push_back(std::move(layers));
  }
}

template <int D>
int OpenBoundaries<D>::grid_axis(const io::BoundaryConfig& side) const {
  return D == 2 && side.axis == 2 ? 1 : side.axis;
}

template <int D>
Real OpenBoundaries<D>::surface_of(const io::BoundaryConfig& side) const {
  return side.depth ? floor_ + *side.depth : std::numeric_limits<Real>::infinity();
}

template <int D>
Real OpenBoundaries<D>::coverage(const io::BoundaryConfig& side, const Vec<D>& x) const {
  if (grid_axis(side) == D - 1) return 1;
  const Real surface = surface_of(side);
  return std::clamp((surface - (x[D - 1] - 0.5 * grid_.h)) / grid_.h, Real(0), Real(1));
}

template <int D>
std::vector<std::size_t> OpenBoundaries<D>::in_layer(const Lattice<D>& lattice, int axis,
                                                     int layer) {
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < lattice.size(); ++k)
    if (lattice.coordinates(k)[axis] == layer) out.push_back(k);
  return out;
}

template <int D>
Real OpenBoundaries<D>::profile_at(const io::BoundaryConfig& side, const Vec<D>& x) const {
  const int a = grid_axis(side);
  const Real surface = surface_of(side);
  if (side.profile == io::InletProfile::kUniform) return 1;
  // A parabola 6 s (1 - s) across each axis of the span, of mean 1.
  Real value = 1;
  for (int b = 0; b < D; ++b) {
    if (b == a) continue;
    const Real lo = grid_.origin[b];
    Real hi = lo + grid_.cells[b] * grid_.h;
    if (b == D - 1) hi = std::min(hi, surface);
    value *= side.profile_across((x[b] - lo) / (hi - lo));
  }
  return value;
}

template <int D>
void OpenBoundaries<D>::apply(SolidFaces<D>& faces, double time) const {
  for (int a = 0; a < D; ++a)
    faces.outlet_pressure[a].assign(faces.open[a].size(), std::numeric_limits<Real>::quiet_NaN());
  for (std::size_t index = 0; index < sides_.size(); ++index) {
    const io::BoundaryConfig& side = sides_[index];
    const int a = grid_axis(side);
    const Lattice<D> lattice = grid_.face_lattice(a);
    const Real inward = side.upper ? -1 : 1;
    const Real speed = side.speed_at(time);
    const Real surface = surface_of(side);
    for (const std::size_t f : layers_[index].faces) {
      const Vec<D> x = lattice.position(lattice.coordinates(f));
      if (side.kind == io::BoundaryKind::kInlet) {
        // Above the surface the side is a wall at rest: the inflow's water cannot leave by it.
        const Real covered = coverage(side, x);
        faces.open[a][f] = 0;
        faces.velocity[a][f] = inward * speed * profile_at(side, x) * covered;
        if (!faces.body[a].empty()) faces.body[a][f] = -1;
      } else {
        faces.open[a][f] = 1;
        faces.velocity[a][f] = 0;
        if (!faces.body[a].empty()) faces.body[a][f] = -1;
        const Real head = std::isfinite(surface) ? std::max(Real(0), surface - x[D - 1]) : 0;
        faces.outlet_pressure[a][f] = side.pressure.value_or(0) + density_ * gravity_ * head;
      }
    }
  }
}

template <int D>
void OpenBoundaries<D>::fill_inflow(CellField& phi) const {
  const Lattice<D> cells = grid_.cell_lattice();
  for (std::size_t index = 0; index < sides_.size(); ++index) {
    const io::BoundaryConfig& side = sides_[index];
    const int a = grid_axis(side);
    const Real surface = surface_of(side);
    for (const std::size_t k : layers_[index].cells) {
      const GridIndex<D> c = cells.coordinates(k);
      // Water below the surface at least; above it the level the water beside has (no
      // gradient), so that the water piled against the side (or drawn down) keeps its level
      // and the side's surface makes no step. With no depth, water a cell deep at least.
      GridIndex<D> inward = c;
      inward[a] += side.upper ? -1 : 1;
      const Real beside = cells.contains(inward) ? phi[cells.index(inward)] : phi[k];
      phi[k] = std::isfinite(surface) ? std::min(beside, cells.position(c)[D - 1] - surface)
                                      : std::min(phi[k], -grid_.h);
    }
  }
}

template <int D>
void OpenBoundaries<D>::fill_inflow(FaceField<D>& u) const {
  for (const Layers& layers : layers_)
    for (int b = 0; b < D; ++b)
      for (const std::size_t f : layers.across[b]) u[b][f] = 0;
}

template <int D>
const io::BoundaryConfig* OpenBoundaries<D>::beyond(int axis, bool upper) const {
  for (const io::BoundaryConfig& side : sides_)
    if (grid_axis(side) == axis && side.upper == upper) return &side;
  return nullptr;
}

template <int D>
double OpenBoundaries<D>::outflow(std::size_t index, const FaceField<D>& u,
                                  const CellField& phi) const {
  const io::BoundaryConfig& side = sides_[index];
  const int a = grid_axis(side);
  const Lattice<D> faces = grid_.face_lattice(a), cells = grid_.cell_lattice();
  const Real outward = side.upper ? 1 : -1;
  const Real area = std::pow(grid_.h, D - 1);
  double sum = 0;
  for (const std::size_t f : layers_[index].faces) {
    GridIndex<D> c = faces.coordinates(f);
    if (side.upper) c[a] -= 1;
    // An inlet's face velocity holds its covered share (0 above the surface).
    const Real water = side.kind == io::BoundaryKind::kInlet
                           ? Real(1)
                           : water_fraction(phi[cells.index(c)], grid_.h);
    sum += outward * u[a][f] * water * area;
  }
  return sum;
}

template class OpenBoundaries<2>;
template class OpenBoundaries<3>;

}  // namespace sluice
