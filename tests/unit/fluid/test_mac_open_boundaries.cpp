// The grid model's open boundaries: an inlet's faces carry its mean speed over the span, an
// outlet's pressure is hydrostatic below its depth, and a projection between the two gives the
// exact potential flow of a channel full of water.
#include <gtest/gtest.h>

#include <cmath>

#include "sluice/fluid/mac/open_boundaries.hpp"
#include "sluice/fluid/mac/pressure_projection.hpp"

namespace sluice {
namespace {

// 2 m x 1 m in cells of `h`.
MacGrid<2> channel(double h) {
  MacGrid<2> grid;
  grid.cells = {static_cast<int>(std::lround(2 / h)), static_cast<int>(std::lround(1 / h))};
  grid.h = h;
  return grid;
}

// A side across x: the lower (an inlet's here) or the upper (an outlet's).
io::BoundaryConfig side_across_x(io::BoundaryKind kind, bool upper) {
  io::BoundaryConfig b;
  b.kind = kind;
  b.axis = 0;
  b.upper = upper;
  return b;
}

io::BoundaryConfig inlet(double speed, io::InletProfile profile = io::InletProfile::kUniform) {
  io::BoundaryConfig b = side_across_x(io::BoundaryKind::kInlet, false);
  b.mean_speed = speed;
  b.profile = profile;
  return b;
}

io::BoundaryConfig outlet(double pressure) {
  io::BoundaryConfig b = side_across_x(io::BoundaryKind::kOutlet, true);
  b.pressure = pressure;
  return b;
}

SolidFaces<2> open_faces(const MacGrid<2>& grid) {
  return {make_face_field(grid, 1.0), make_face_field(grid, 0.0), {}, {}};
}

// The flux into the grid through its x- side.
double inflow(const MacGrid<2>& grid, const SolidFaces<2>& faces) {
  const Lattice<2> lattice = grid.face_lattice(0);
  double sum = 0;
  for (std::size_t f = 0; f < lattice.size(); ++f)
    if (lattice.coordinates(f)[0] == 0) sum += faces.velocity[0][f] * grid.h;
  return sum;
}

TEST(MacOpenBoundaries, InletCarriesItsMeanSpeedBelowItsDepthAndIsAWallAbove) {
  const MacGrid<2> grid = channel(0.1);
  io::BoundaryConfig side = inlet(0.5);
  side.depth = 0.63;  // across a cell: its faces' shares
  OpenBoundaries<2> open(grid, {side}, 1000, 9.81, 0);
  SolidFaces<2> faces = open_faces(grid);
  open.apply(faces, 0);
  EXPECT_NEAR(inflow(grid, faces), 0.5 * 0.63, 1e-12);
  const Lattice<2> lattice = grid.face_lattice(0);
  for (std::size_t f = 0; f < lattice.size(); ++f) {
    const GridIndex<2> c = lattice.coordinates(f);
    if (c[0] != 0) continue;
    // Closed all the way up: above the surface the side is a wall at rest.
    EXPECT_EQ(faces.open[0][f], 0.0) << "face " << c[1];
    if (c[1] >= 7) {
      EXPECT_EQ(faces.velocity[0][f], 0.0) << "face " << c[1];
    }
  }
}

TEST(MacOpenBoundaries, ParabolicInletIsTheMidpointSumOfItsParabola) {
  // 6 s (1 - s) of mean 1, summed at N midpoints: 1 + 1 / (2 N^2).
  for (const double h : {0.25, 0.05}) {
    const MacGrid<2> grid = channel(h);
    OpenBoundaries<2> open(grid, {inlet(0.2, io::InletProfile::kParabolic)}, 1, 0, 0);
    SolidFaces<2> faces = open_faces(grid);
    open.apply(faces, 0);
    const double n = grid.cells[1];
    EXPECT_NEAR(inflow(grid, faces), 0.2 * (1 + 1 / (2 * n * n)), 1e-12) << "h " << h;
  }
}

// In 3D the product of one parabola per axis across: its midpoint sum, squared.
TEST(MacOpenBoundaries, ParabolicInletIn3DIsTheProductOfTwoParabolas) {
  MacGrid<3> grid;
  grid.cells = {4, 6, 6};
  grid.h = 0.2;
  io::BoundaryConfig side = inlet(0.3, io::InletProfile::kParabolic);
  side.axis = 1;  // across y
  OpenBoundaries<3> open(grid, {side}, 1, 0, 0);
  SolidFaces<3> faces{make_face_field(grid, 1.0), make_face_field(grid, 0.0), {}, {}};
  open.apply(faces, 0);
  const Lattice<3> lattice = grid.face_lattice(1);
  double sum = 0, area = 0;
  for (std::size_t f = 0; f < lattice.size(); ++f) {
    if (lattice.coordinates(f)[1] != 0) continue;
    sum += faces.velocity[1][f] * grid.h * grid.h;
    area += grid.h * grid.h;
  }
  const double per_axis_x = 1 + 1 / (2.0 * 4 * 4), per_axis_z = 1 + 1 / (2.0 * 6 * 6);
  EXPECT_NEAR(sum, 0.3 * area * per_axis_x * per_axis_z, 1e-12);
}

TEST(MacOpenBoundaries, OutletPressureIsHydrostaticBelowItsDepth) {
  const MacGrid<2> grid = channel(0.1);
  io::BoundaryConfig side = outlet(50);
  side.depth = 0.4;
  OpenBoundaries<2> open(grid, {side}, 1000, 9.81, 0);
  SolidFaces<2> faces = open_faces(grid);
  open.apply(faces, 0);
  const Lattice<2> lattice = grid.face_lattice(0);
  for (std::size_t f = 0; f < lattice.size(); ++f) {
    const GridIndex<2> c = lattice.coordinates(f);
    const double p = faces.outlet_pressure[0][f];
    if (c[0] != grid.cells[0]) {
      EXPECT_TRUE(std::isnan(p));
      continue;
    }
    const double z = (c[1] + 0.5) * grid.h;
    EXPECT_NEAR(p, 50 + 1000 * 9.81 * std::max(0.0, 0.4 - z), 1e-9) << "z " << z;
  }
}

TEST(MacOpenBoundaries, InflowCellsAreWaterBelowTheSurface) {
  const MacGrid<2> grid = channel(0.1);
  io::BoundaryConfig side = inlet(0.5);
  side.depth = 0.45;
  OpenBoundaries<2> open(grid, {side}, 1000, 9.81, 0);
  CellField phi(grid.cell_count(), 1.0);
  open.fill_inflow(phi);
  const Lattice<2> cells = grid.cell_lattice();
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const GridIndex<2> c = cells.coordinates(k);
    const double expected = c[0] == 0 ? (c[1] + 0.5) * 0.1 - 0.45 : 1.0;
    EXPECT_NEAR(phi[k], expected, 1e-12);
  }
}

// A channel full of water between closed floor and roof, at rest, and an inlet of speed U set
// going: the projection gives the uniform flow U everywhere and the pressure that drives it,
// linear from the outlet's p_out: p = p_out + rho U (L - x) / dt.
TEST(MacOpenBoundaries, ProjectionBetweenInletAndOutletGivesTheChannelsPotentialFlow) {
  const MacGrid<2> grid = channel(0.1);
  const double speed = 0.3, p_out = 20, dt = 0.01, rho = 1000;
  OpenBoundaries<2> open(grid, {inlet(speed), outlet(p_out)}, rho, 0, 0);
  SolidFaces<2> faces = open_faces(grid);
  const Lattice<2> vertical = grid.face_lattice(1);
  for (std::size_t f = 0; f < vertical.size(); ++f) {
    const int layer = vertical.coordinates(f)[1];
    if (layer == 0 || layer == grid.cells[1]) faces.open[1][f] = 0;  // floor and roof
  }
  open.apply(faces, 0);
  const CellField phi(grid.cell_count(), -1.0);
  FaceField<2> u = make_face_field(grid);
  CellField pressure;
  FaceMarks<2> valid;
  PressureProjection<2> projection(make_sparse_solver("cg_incomplete_cholesky", {1e-12, 5000}));
  std::vector<ProjectedBody> no_bodies;
  projection.project(grid, phi, faces, dt, rho, u, pressure, valid, no_bodies);
  for (const double v : u[0]) EXPECT_NEAR(v, speed, 1e-8);
  for (const double v : u[1]) EXPECT_NEAR(v, 0, 1e-8);
  const Lattice<2> cells = grid.cell_lattice();
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const double x = cells.position(cells.coordinates(k))[0];
    EXPECT_NEAR(pressure[k], p_out + rho * speed * (2 - x) / dt, 1e-5 * rho * speed / dt);
  }
  EXPECT_NEAR(open.outflow(1, u, phi), speed * 1.0, 1e-8);
  EXPECT_NEAR(open.outflow(0, u, phi), -speed * 1.0, 1e-8);
}

}  // namespace
}  // namespace sluice
