// The grid model's operators: sampling, advection, velocity extension and the pressure
// projection (its Poisson problem against exact solutions, with the order of convergence).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "physics/reported_figure.hpp"
#include "sluice/fluid/mac/advection.hpp"
#include "sluice/fluid/mac/mac_grid.hpp"
#include "sluice/fluid/mac/pressure_projection.hpp"
#include "sluice/fluid/mac/velocity_extension.hpp"

namespace sluice {
namespace {

using testing::Bound;
using testing::expect_figure;

MacGrid<2> unit_square(int n) {
  MacGrid<2> grid;
  grid.cells = {n, n};
  grid.h = 1.0 / n;
  return grid;
}

TEST(MacLattice, SamplesLinearFieldsExactlyAndExtrapolatesHalfACell) {
  const MacGrid<2> grid = unit_square(8);
  const Lattice<2> cells = grid.cell_lattice();
  auto field = [](const Vec<2>& x) { return 2 + 3 * x[0] - 5 * x[1]; };
  std::vector<Real> values(cells.size());
  for (std::size_t k = 0; k < values.size(); ++k)
    values[k] = field(cells.position(cells.coordinates(k)));
  for (const Vec<2>& x : {Vec<2>(0.3, 0.7), Vec<2>(0.0625, 0.5), Vec<2>(0.91, 0.12)})
    EXPECT_NEAR(cells.sample(values, x), field(x), 1e-12);
  // The floor, half a cell below the first centres: clamped without reach, exact with it.
  const Vec<2> floor(0.5, 0.0);
  EXPECT_NEAR(cells.sample(values, floor, nullptr, nullptr, 0.5), field(floor), 1e-12);
  EXPECT_NEAR(cells.sample(values, floor), field(Vec<2>(0.5, 0.0625)), 1e-12);
}

// A periodic axis: as many faces as cells along it, indices and samples read across the seam
// (a field periodic on the grid is sampled exactly as its linear interpolation across it), and
// a point past a side comes back through the other.
TEST(MacLattice, APeriodicAxisRepeatsEveryLattice) {
  MacGrid<2> grid;
  grid.cells = {8, 4};
  grid.h = 0.25;  // x in [0, 2)
  grid.periodic_axis = 0;
  EXPECT_EQ(grid.face_lattice(0).dims[0], 8);
  EXPECT_EQ(grid.face_lattice(1).dims[1], 5);
  EXPECT_EQ(grid.node_lattice().dims[0], 8);
  EXPECT_FALSE(grid.on_boundary(0, 0));
  EXPECT_TRUE(grid.on_boundary(1, 0));
  const Lattice<2> cells = grid.cell_lattice();
  EXPECT_TRUE(cells.contains({-1, 0}));
  EXPECT_FALSE(cells.contains({0, 4}));
  EXPECT_EQ(cells.index({-1, 2}), cells.index({7, 2}));
  EXPECT_EQ(cells.index({8, 2}), cells.index({0, 2}));
  std::vector<Real> values(cells.size());
  for (std::size_t k = 0; k < values.size(); ++k) values[k] = cells.coordinates(k)[0];  // 0..7
  // Halfway between the last cell's centre (x = 1.875, value 7) and the first's beyond the
  // seam (x = 2.125, value 0), and the same a period on.
  EXPECT_DOUBLE_EQ(cells.sample(values, Vec<2>(2.0, 0.5)), 3.5);
  EXPECT_DOUBLE_EQ(cells.sample(values, Vec<2>(0.0, 0.5)), 3.5);
  EXPECT_DOUBLE_EQ(cells.sample(values, Vec<2>(0.875 + 4.0, 0.5)), 3.0);
  EXPECT_DOUBLE_EQ(grid.wrapped(Vec<2>(2.1, 0.3))[0], 2.1 - 2.0);
  EXPECT_DOUBLE_EQ(grid.wrapped(Vec<2>(-0.1, 0.3))[0], 1.9);
  EXPECT_DOUBLE_EQ(grid.wrapped(Vec<2>(-0.1, 0.3))[1], 0.3);
}

// A smooth bump carried across the grid by a uniform flow and back: MacCormack's error is at
// most a third of plain semi-Lagrangian's, and it makes no new extremum.
TEST(MacAdvection, MacCormackBeatsSemiLagrangianWithoutNewExtrema) {
  const MacGrid<2> grid = unit_square(64);
  const Lattice<2> cells = grid.cell_lattice();
  FaceField<2> u = make_face_field(grid);
  std::fill(u[0].begin(), u[0].end(), 1.0);
  std::fill(u[1].begin(), u[1].end(), 0.5);
  auto bump = [](const Vec<2>& x) {
    return std::exp(-((x - Vec<2>(0.35, 0.4)).squaredNorm()) / (2 * 0.08 * 0.08));
  };
  std::vector<Real> start(cells.size());
  for (std::size_t k = 0; k < start.size(); ++k)
    start[k] = bump(cells.position(cells.coordinates(k)));
  const double dt = 0.4 * grid.h;  // CFL 0.4
  const int steps = 25;
  std::vector<Real> sl = start, mc = start;
  for (int s = 0; s < steps; ++s) {
    sl = advect_semi_lagrangian(cells, sl, grid, u, dt);
    mc = advect_maccormack(cells, mc, grid, u, dt);
  }
  double error_sl = 0, error_mc = 0, largest = -1, smallest = 1;
  for (std::size_t k = 0; k < start.size(); ++k) {
    const Vec<2> x = cells.position(cells.coordinates(k)) - steps * dt * Vec<2>(1.0, 0.5);
    error_sl = std::max(error_sl, std::abs(sl[k] - bump(x)));
    error_mc = std::max(error_mc, std::abs(mc[k] - bump(x)));
    largest = std::max(largest, mc[k]);
    smallest = std::min(smallest, mc[k]);
  }
  expect_figure(
      {"MacCormack's largest error over semi-Lagrangian's, a bump carried 25 steps", "", 3},
      error_mc / error_sl, Bound::below, 1.0 / 3);
  expect_figure({"MacCormack's largest value (the bump's peak 1)", "", 4}, largest, Bound::below,
                1.0);
  expect_figure({"MacCormack's smallest value (the bump's floor 0)", "", 4}, smallest, Bound::above,
                0.0);
}

// A flat surface at z = 0.5 with water below; the water's u varies with x alone. Extension
// along the surface's normal (vertical) carries each column's value up unchanged.
TEST(MacExtension, CarriesValuesAlongTheNormal) {
  const MacGrid<2> grid = unit_square(16);
  const Lattice<2> cells = grid.cell_lattice();
  CellField phi(cells.size());
  for (std::size_t k = 0; k < phi.size(); ++k)
    phi[k] = cells.position(cells.coordinates(k))[1] - 0.5;
  FaceField<2> u = make_face_field(grid);
  FaceMarks<2> known;
  for (int a = 0; a < 2; ++a) {
    const Lattice<2> faces = grid.face_lattice(a);
    known[a].assign(faces.size(), 0);
    const std::vector<Real> level = phi_at_faces(grid, phi, a);
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const Vec<2> x = faces.position(faces.coordinates(f));
      if (level[f] < 0) {
        u[a][f] = a == 0 ? 1 + 2 * x[0] : -x[0];
        known[a][f] = 1;
      } else {
        u[a][f] = 99;  // to be replaced
      }
    }
  }
  extend_velocity<2>(grid, phi, known, u);
  double worst = 0;
  for (int a = 0; a < 2; ++a) {
    const Lattice<2> faces = grid.face_lattice(a);
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const Vec<2> x = faces.position(faces.coordinates(f));
      worst = std::max(worst, std::abs(u[a][f] - (a == 0 ? 1 + 2 * x[0] : -x[0])));
    }
  }
  expect_figure({"extension of a field varying along the surface, largest error", "m/s", -1}, worst,
                Bound::below, 1e-12);
}

// The pressure of one projection (dt = 1, density 1, the velocity before it 0) on water
// between a solid disc of radius r1 at the centre and a free surface, the circle of radius r2:
// the solid's faces carry a source flow V r1 x / |x|^2, so the exact pressure is the potential
// -V r1 ln(|x| / r2), zero on the free surface. Both cut boundaries at once: the disc through
// the open fractions of its faces, the surface through the ghost fluid.
double annulus_pressure_error(int n) {
  const MacGrid<2> grid = unit_square(n);
  const Lattice<2> cells = grid.cell_lattice();
  const Lattice<2> nodes = grid.node_lattice();
  const Vec<2> centre(0.5, 0.5);
  const double r1 = 0.15, r2 = 0.4, speed = 1.0;
  CellField phi(cells.size());
  for (std::size_t k = 0; k < phi.size(); ++k)
    phi[k] = (cells.position(cells.coordinates(k)) - centre).norm() - r2;
  SolidFaces<2> solid{make_face_field(grid, 1.0), make_face_field(grid, 0.0), {}, {}};
  for (int a = 0; a < 2; ++a) {
    const Lattice<2> faces = grid.face_lattice(a);
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const GridIndex<2> c = faces.coordinates(f);
      GridIndex<2> other = c;
      other[1 - a] += 1;  // the face's two corners
      const double d0 = (nodes.position(c) - centre).norm() - r1;
      const double d1 = (nodes.position(other) - centre).norm() - r1;
      solid.open[a][f] = positive_fraction(d0, d1);
      const Vec<2> r = faces.position(c) - centre;
      solid.velocity[a][f] = speed * r1 * r[a] / r.squaredNorm();
    }
  }
  FaceField<2> u = make_face_field(grid);
  CellField pressure;
  FaceMarks<2> valid;
  PressureProjection<2> projection(make_sparse_solver("cg_incomplete_cholesky", {1e-12, 5000}));
  std::vector<ProjectedBody> no_bodies;
  const ProjectionReport report =
      projection.project(grid, phi, solid, 1.0, 1.0, u, pressure, valid, no_bodies);
  EXPECT_TRUE(report.converged);
  double worst = 0;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const double r = (cells.position(cells.coordinates(k)) - centre).norm();
    if (r < r1 + grid.h || phi[k] >= 0) continue;  // water cells clear of the disc's cut cells
    // pressure [Pa] = q rho h / dt; the exact potential is in m^2/s (dt = rho = 1).
    worst = std::max(worst, std::abs(pressure[k] - (-speed * r1 * std::log(r / r2))));
  }
  return worst;
}

TEST(MacProjection, CutCellPoissonConvergesAtSecondOrder) {
  const double coarse = annulus_pressure_error(32), medium = annulus_pressure_error(64),
               fine = annulus_pressure_error(128);
  expect_figure({"cut-cell Poisson on an annulus, order from 32 to 64 cells", "", 2},
                std::log2(coarse / medium), Bound::above, 1.7);
  expect_figure({"cut-cell Poisson on an annulus, order from 64 to 128 cells", "", 2},
                std::log2(medium / fine), Bound::above, 1.7);
}

// After a projection, every water cell's weighted divergence (open part of each face at the
// fluid's velocity, the rest at the solid's) is zero to the solver's tolerance.
TEST(MacProjection, LeavesNoDivergenceBesideAMovingSolid) {
  const MacGrid<2> grid = unit_square(32);
  const Lattice<2> cells = grid.cell_lattice();
  const Lattice<2> nodes = grid.node_lattice();
  CellField phi(cells.size(), -1.0);  // all water, closed box
  SolidFaces<2> solid{make_face_field(grid, 1.0), make_face_field(grid, 0.0), {}, {}};
  for (int a = 0; a < 2; ++a) {
    const Lattice<2> faces = grid.face_lattice(a);
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const GridIndex<2> c = faces.coordinates(f);
      if (c[a] == 0 || c[a] == grid.cells[a]) {
        solid.open[a][f] = 0;  // the box's walls
        continue;
      }
      GridIndex<2> other = c;
      other[1 - a] += 1;
      const double d0 = (nodes.position(c) - Vec<2>(0.4, 0.55)).norm() - 0.13;
      const double d1 = (nodes.position(other) - Vec<2>(0.4, 0.55)).norm() - 0.13;
      solid.open[a][f] = positive_fraction(d0, d1);
      solid.velocity[a][f] = a == 0 ? 0.7 : -0.2;  // the disc moves; the fluid must make way
    }
  }
  FaceField<2> u = make_face_field(grid);
  CellField pressure;
  FaceMarks<2> valid;
  PressureProjection<2> projection(make_sparse_solver("cg_incomplete_cholesky", {1e-10, 5000}));
  std::vector<ProjectedBody> no_bodies;
  projection.project(grid, phi, solid, 0.01, 1000.0, u, pressure, valid, no_bodies);
  double worst = 0;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const GridIndex<2> c = cells.coordinates(k);
    double divergence = 0;
    bool open = false;
    for (int a = 0; a < 2; ++a) {
      for (int side = 0; side < 2; ++side) {
        GridIndex<2> f = c;
        f[a] += side;
        const std::size_t m = grid.face_lattice(a).index(f);
        const double w = solid.open[a][m];
        open = open || w > 0;
        divergence += (side ? 1 : -1) * (w * u[a][m] + (1 - w) * solid.velocity[a][m]);
      }
    }
    if (open) worst = std::max(worst, std::abs(divergence));
  }
  expect_figure({"divergence left beside a moving disc, largest", "m/s", -1}, worst, Bound::below,
                1e-7);
}

}  // namespace
}  // namespace sluice
