// The solids as the grid sees them: the signed distance to the walls and bodies at the cells'
// corners, each face's open fraction from it, and the solid's velocity on each face (a body's
// rigid motion, a wall's surface velocity). The walls are sampled once; the bodies each time
// they move, only near each body.
#pragma once

#include <vector>

#include "sluice/coupling/body_geometry.hpp"
#include "sluice/fluid/mac/mac_grid.hpp"
#include "sluice/fluid/mac/open_boundaries.hpp"
#include "sluice/fluid/mac/pressure_projection.hpp"

namespace sluice {

template <int D>
class SolidBoundary {
 public:
  // `open`: the inlets and outlets, which take the place of any wall on their sides.
  SolidBoundary(const MacGrid<D>& grid, const BodyGeometry& geometry, OpenBoundaries<D> open = {});

  // The faces with the bodies at `motion`.
  void place_bodies(const std::vector<BodyKinematics>& motion);
  // The inlets' faces at `time`.
  void at_time(double time);
  const OpenBoundaries<D>& open_boundaries() const { return open_; }

  const SolidFaces<D>& faces() const { return faces_; }
  // Signed distance to the nearest solid at the cells' corners (negative inside).
  const std::vector<Real>& node_distance() const { return nodes_; }
  // Whether the centre of a cell lies inside a solid.
  bool cell_is_solid(std::size_t cell) const { return solid_cell_[cell] != 0; }
  const std::vector<char>& solid_cells() const { return solid_cell_; }
  // The velocity of the solid beyond the grid's boundary at x (a wall's surface velocity).
  Vec<D> wall_velocity_at(const Vec<D>& x) const;

 private:
  // Open fractions and velocities of every face from nodes_, the bodies at `motion`.
  void fill_faces(const std::vector<BodyKinematics>& motion);

  MacGrid<D> grid_;
  const BodyGeometry* geometry_;
  OpenBoundaries<D> open_;
  double time_ = 0;
  std::vector<Real> wall_nodes_;
  std::vector<Real> nodes_;
  std::vector<int> nearest_body_;  // per node: the body that sets its distance, or -1 (walls)
  std::vector<Real> body_reach_;   // per body: the largest distance of its surface from its centre
  SolidFaces<D> faces_;
  std::vector<char> solid_cell_;
};

}  // namespace sluice
