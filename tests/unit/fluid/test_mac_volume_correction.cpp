// The grid model's volume correction: the water a level set holds, what crosses the grid's
// boundary, and the shift that gives back what advection lost.
#include <gtest/gtest.h>

#include <vector>

#include "sluice/fluid/mac/free_surface.hpp"
#include "sluice/fluid/mac/volume_correction.hpp"

namespace sluice {
namespace {

// 20 x 20 cells of 0.1 m, the surface flat at `level`.
MacGrid<2> box() {
  MacGrid<2> grid;
  grid.cells.fill(20);
  grid.h = 0.1;
  return grid;
}

CellField flat(const MacGrid<2>& grid, double level) {
  const Lattice<2> cells = grid.cell_lattice();
  CellField phi(cells.size());
  for (std::size_t k = 0; k < phi.size(); ++k)
    phi[k] = cells.position(cells.coordinates(k))[1] - level;
  return phi;
}

SolidFaces<2> closed(const MacGrid<2>& grid) {
  return {make_face_field(grid, 0.0), make_face_field(grid, 0.0), {}, {}};
}

// The faces of the top side.
std::vector<std::size_t> top_faces(const MacGrid<2>& grid) {
  const Lattice<2> faces = grid.face_lattice(1);
  std::vector<std::size_t> out;
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (faces.coordinates(f)[1] == grid.cells[1]) out.push_back(f);
  return out;
}

// A flat surface holds its depth times the width, to rounding, wherever it lies in its cell;
// cells left out hold nothing.
TEST(MacVolumeCorrection, FlatSurfaceHoldsItsDepthTimesTheWidth) {
  const MacGrid<2> grid = box();
  const std::vector<char> none(grid.cell_count(), 0);
  for (const double level : {0.73, 0.75, 1.2049})
    EXPECT_NEAR(water_volume_of(grid, flat(grid, level), none), 2 * level, 1e-12);
  std::vector<char> first_column(grid.cell_count(), 0);
  const Lattice<2> cells = grid.cell_lattice();
  for (int j = 0; j < grid.cells[1]; ++j) first_column[cells.index({0, j})] = 1;
  EXPECT_NEAR(water_volume_of(grid, flat(grid, 0.73), first_column), 1.9 * 0.73, 1e-12);
}

// The shift that restores a volume raises a flat surface by the volume over the width, within
// its cell and across a cell's face (where Newton's method meets a kink), and is at most a
// quarter of a cell.
TEST(MacVolumeCorrection, ShiftRaisesAFlatSurfaceByTheMissingVolume) {
  const MacGrid<2> grid = box();
  const std::vector<char> none(grid.cell_count(), 0);
  for (const double target : {1.56, 1.6, 1.62}) {  // levels 0.78, 0.8 (a face), 0.81
    CellField phi = flat(grid, 0.79);
    const VolumeShift shifted = shift_to_volume(grid, phi, none, target);
    EXPECT_NEAR(shifted.shift, 0.79 - target / 2, 1e-12) << target;
    EXPECT_NEAR(shifted.added, target - 1.58, 1e-12) << target;
    EXPECT_NEAR(water_volume_of(grid, phi, none), target, 1e-12) << target;
  }
  CellField phi = flat(grid, 0.73);
  EXPECT_NEAR(shift_to_volume(grid, phi, none, 3.0).shift, -0.025, 1e-12);
  // No surface (all water): nothing to shift.
  CellField full(grid.cell_count(), -1.0);
  EXPECT_EQ(shift_to_volume(grid, full, none, 3.0).shift, 0);
}

// Water leaving across the open top counts, air coming in across it does not; a closed top
// lets nothing through whatever velocity the extension left on it; an outlet brings in what
// the cell beside it holds.
TEST(MacVolumeCorrection, BoundaryInflowCountsTheWaterThatCrosses) {
  const MacGrid<2> grid = box();
  const CellField water(grid.cell_count(), -1.0);
  const double dt = 0.01;
  auto through_top = [&](double velocity, double open, double outlet_pressure) {
    FaceField<2> u = make_face_field(grid);
    SolidFaces<2> faces = closed(grid);
    faces.outlet_pressure = make_face_field(grid, std::nan(""));
    for (const std::size_t f : top_faces(grid)) {
      u[1][f] = velocity;
      faces.open[1][f] = open;
      faces.outlet_pressure[1][f] = outlet_pressure;
    }
    return boundary_inflow<2>(grid, u, water, faces, dt);
  };
  EXPECT_NEAR(through_top(1.0, 1, std::nan("")), -2 * dt, 1e-15);  // out: 2 m wide at 1 m/s
  EXPECT_EQ(through_top(-1.0, 1, std::nan("")), 0);                // in: air
  EXPECT_EQ(through_top(1.0, 0, std::nan("")), 0);                 // a wall
  EXPECT_NEAR(through_top(-1.0, 1, 0.0), 2 * dt, 1e-15);           // into an outlet's water
}

// Once shifted, the surface stays where the shifts put it: the marker particles move with it
// (else the air's markers beside it, a little nearer the surface after each shift, at last find
// themselves in the water and take the shifts back). Twenty shifts of 0.004 m^2, a step
// without flow after each.
TEST(MacVolumeCorrection, MarkersFollowTheShift) {
  const MacGrid<2> grid = box();
  const std::vector<char> none(grid.cell_count(), 0);
  FreeSurface<2> surface(grid, flat(grid, 0.73), 16, 5);
  const FaceField<2> still = make_face_field(grid);
  double added = 0;
  for (int step = 1; step <= 20; ++step) {
    added += surface.keep_volume(none, 1.46 + 0.004 * step);
    surface.advance(still, 0.01, closed(grid));
  }
  EXPECT_NEAR(added, 0.08, 1e-3);
  EXPECT_NEAR(water_volume_of(grid, surface.phi(), none), 1.54, 1e-3);
}

}  // namespace
}  // namespace sluice
