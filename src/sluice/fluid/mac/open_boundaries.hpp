// The case's open sides as the grid sees them: an inlet's faces closed to the pressure and
// moving at the inflow's velocity (a solid face that lets water through), with water below its
// depth in the cells beside it; an outlet's faces open, the pressure beyond them prescribed
// (hydrostatic below a depth) as a Dirichlet condition on the side itself.
#pragma once

#include <array>
#include <vector>

#include "sluice/fluid/mac/pressure_projection.hpp"
#include "sluice/io/boundary_config.hpp"

namespace sluice {

template <int D>
class OpenBoundaries {
 public:
  OpenBoundaries() = default;
  // `domain_floor`: the height the depths are measured from; `gravity`: its downward magnitude.
  OpenBoundaries(const MacGrid<D>& grid, std::vector<io::BoundaryConfig> sides, Real density,
                 Real gravity, Real domain_floor);

  bool empty() const { return sides_.empty(); }
  // The boundary faces at `time`: an inlet's closed with the inflow's normal velocity, an
  // outlet's open with their pressure in `faces.outlet_pressure` (NaN elsewhere).
  void apply(SolidFaces<D>& faces, double time) const;
  // The level set in the cells beside each inlet: the surface at its depth (no depth: water).
  void fill_inflow(CellField& phi) const;
  // The velocity across each inlet in the cells beside it, after advection: the inflow's, 0
  // (advection from beyond the grid would carry the cells' own).
  void fill_inflow(FaceField<D>& u) const;
  // What lies beyond the grid on the side along grid axis `axis`: an inlet, an outlet, or
  // neither (null: a wall or air).
  const io::BoundaryConfig* beyond(int axis, bool upper) const;
  // The volume flux [m^3/s, 2D: m^2/s] of water out of the grid through side `index` (the
  // case's order) in `u`: each face's by the water's share of the cell beside it (of level set
  // `phi`), an inlet's by the share of the face below its surface as it was set.
  double outflow(std::size_t index, const FaceField<D>& u, const CellField& phi) const;

 private:
  // The grid axis of a side, and the faces on it.
  int grid_axis(const io::BoundaryConfig& side) const;
  // The points of `lattice` whose coordinate along `axis` is `layer`.
  static std::vector<std::size_t> in_layer(const Lattice<D>& lattice, int axis, int layer);
  // The inflow's speed at face position x (the side's profile at mean speed 1).
  Real profile_at(const io::BoundaryConfig& side, const Vec<D>& x) const;
  Real surface_of(const io::BoundaryConfig& side) const;
  // The share of the face at x below the side's surface.
  Real coverage(const io::BoundaryConfig& side, const Vec<D>& x) const;

  MacGrid<D> grid_;
  std::vector<io::BoundaryConfig> sides_;
  // What each side touches, found once: its faces; an inlet's the cells beside it and the faces
  // across it in those cells (`across[b]`: of axis b, none along the side's own).
  struct Layers {
    std::vector<std::size_t> faces, cells;
    std::array<std::vector<std::size_t>, D> across;
  };
  std::vector<Layers> layers_;
  Real density_ = 1000, gravity_ = 0, floor_ = 0;
};

}  // namespace sluice
