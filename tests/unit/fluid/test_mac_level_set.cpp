// The grid model's free surface: reinitialisation, the particle level set on Zalesak's disk,
// and the surface mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "physics/reported_figure.hpp"
#include "sluice/fluid/mac/free_surface.hpp"
#include "sluice/fluid/mac/level_set.hpp"
#include "sluice/fluid/mac/surface_mesh.hpp"

namespace sluice {
namespace {

using testing::Bound;
using testing::expect_figure;

template <int D>
MacGrid<D> cube(int n, double size) {
  MacGrid<D> grid;
  grid.cells.fill(n);
  grid.h = size / n;
  return grid;
}

template <int D, class F>
CellField on_cells(const MacGrid<D>& grid, F&& f) {
  const Lattice<D> cells = grid.cell_lattice();
  CellField out(cells.size());
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = f(cells.position(cells.coordinates(k)));
  return out;
}

// A circle's level set scaled unevenly (not a distance) becomes the distance again: within a
// twentieth of a cell of it beside the surface, a tenth in the band of three cells around it.
TEST(MacLevelSet, ReinitialisationRestoresTheDistance) {
  const MacGrid<2> grid = cube<2>(64, 1.0);
  const Vec<2> centre(0.52, 0.47);
  const double radius = 0.3;
  CellField phi = on_cells(grid, [&](const Vec<2>& x) {
    return ((x - centre).norm() - radius) * (0.3 + 2 * x[0] * x[0]);
  });
  reinitialise<2>(grid, phi);
  const CellField exact =
      on_cells(grid, [&](const Vec<2>& x) { return (x - centre).norm() - radius; });
  double worst = 0, near = 0;
  for (std::size_t k = 0; k < phi.size(); ++k) {
    if (std::abs(exact[k]) < 3 * grid.h) worst = std::max(worst, std::abs(phi[k] - exact[k]));
    if (std::abs(exact[k]) < grid.h) near = std::max(near, std::abs(phi[k] - exact[k]));
  }
  // The surface stays where it was.
  expect_figure({"reinitialised circle, largest error beside the surface [cells]", "", 3},
                near / grid.h, Bound::below, 0.05);
  expect_figure({"reinitialised circle, largest error in the band of 3 cells [cells]", "", 3},
                worst / grid.h, Bound::below, 0.1);
}

// Zalesak's disk (Zalesak, JCP 31, 1979; the set-up of Enright et al. 2002, section 5.1): a
// slotted disk of radius 15 in a 100 x 100 box turned once about the box's centre, on 100 x 100
// cells. The marker particles keep its area within 2.5 %, and closer than the level set alone.
double zalesak_area_error(int particles_per_cell, int every) {
  const MacGrid<2> grid = cube<2>(100, 100.0);
  const Vec<2> centre(50, 75);
  auto slotted_disk = [&](const Vec<2>& x) {
    const double disk = (x - centre).norm() - 15;
    // The slot: 5 wide, from the disk's bottom up to 10 below its top.
    const double slot_x = std::abs(x[0] - 50) - 2.5;
    const double slot_y = x[1] - 85;
    const double in_slot = std::max(slot_x, slot_y);
    return std::max(disk, -in_slot);
  };
  CellField phi = on_cells(grid, slotted_disk);
  reinitialise<2>(grid, phi);
  FreeSurface<2> surface(grid, phi, particles_per_cell, every);
  FaceField<2> u = make_face_field(grid);
  const double omega = std::numbers::pi / 314;  // one turn in 628 s
  for (int a = 0; a < 2; ++a) {
    const Lattice<2> faces = grid.face_lattice(a);
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const Vec<2> x = faces.position(faces.coordinates(f));
      u[a][f] = a == 0 ? omega * (50 - x[1]) : omega * (x[0] - 50);
    }
  }
  auto area = [&](const CellField& phi) {
    double sum = 0;
    for (const double p : phi) sum += std::clamp(0.5 - p / grid.h, 0.0, 1.0);
    return sum * grid.h * grid.h;
  };
  const double start = area(surface.phi());
  const SolidFaces<2> closed_box{make_face_field(grid, 0.0), make_face_field(grid, 0.0), {}, {}};
  const int steps = 628;
  for (int s = 0; s < steps; ++s) surface.advance(u, 628.0 / steps, closed_box);
  return std::abs(area(surface.phi()) / start - 1);
}

TEST(MacLevelSet, ParticleLevelSetKeepsZalesaksDisk) {
  // Reinitialised every 5 steps, the model's default.
  const double without = zalesak_area_error(0, 5);
  const double with = zalesak_area_error(16, 5);
  expect_figure(
      {"Zalesak's disk after a turn, area error with 16 markers per cell and sign", "%", 2},
      100 * with, Bound::below, 2.5);
  expect_figure({"Zalesak's disk, area error with markers over the level set's alone", "", 3},
                with / without, Bound::below, 0.7);
}

// A box full to its top with water draining downwards at 1 m/s: through a top open to air the
// air comes in behind the water, and after 2 s the surface lies 2 m below the top (within half
// a cell); under a closed top the level set is held (the projection, not tested here, would
// stop the flow). Before the air was let in, a cell of water under an open top stayed water for
// ever.
TEST(MacLevelSet, AirComesInWhereTheFlowEntersAcrossAnOpenBoundary) {
  const MacGrid<2> grid = cube<2>(16, 8.0);  // cells of 0.5 m
  FaceField<2> u = make_face_field(grid);
  for (double& v : u[1]) v = -1;
  auto surface_after = [&](double top_open) {
    FreeSurface<2> surface(grid, on_cells(grid, [](const Vec<2>& x) { return x[1] - 8; }), 0, 5);
    SolidFaces<2> faces{make_face_field(grid, 0.0), make_face_field(grid, 0.0), {}, {}};
    const Lattice<2> y_faces = grid.face_lattice(1);
    for (std::size_t f = 0; f < y_faces.size(); ++f)
      if (y_faces.coordinates(f)[1] == grid.cells[1]) faces.open[1][f] = top_open;
    for (int step = 0; step < 20; ++step) surface.advance(u, 0.1, faces);
    // The highest crossing on the middle column.
    const Lattice<2> cells = grid.cell_lattice();
    for (int j = grid.cells[1] - 1; j > 0; --j) {
      const double above = surface.phi()[cells.index({8, j})];
      const double below = surface.phi()[cells.index({8, j - 1})];
      if (above >= 0 && below < 0) return (j - 0.5) * grid.h + grid.h * below / (below - above);
    }
    return surface.phi()[cells.index({8, grid.cells[1] - 1})] < 0 ? 8.0 : 0.0;
  };
  EXPECT_NEAR(surface_after(1.0), 6.0, 0.25);
  EXPECT_EQ(surface_after(0.0), 8.0);
}

// The surface mesh of a circle is as long as the circle, of a sphere as large as the sphere,
// to 1 % on 64 cells across.
TEST(MacSurfaceMesh, MeasuresCircleAndSphere) {
  const double radius = 0.3;
  const MacGrid<2> square = cube<2>(64, 1.0);
  const std::vector<Vec3> lines = surface_mesh<2>(square, on_cells(square, [&](const Vec<2>& x) {
                                                    return (x - Vec<2>(0.5, 0.5)).norm() - radius;
                                                  }));
  double length = 0;
  for (std::size_t k = 0; k < lines.size(); k += 2) length += (lines[k + 1] - lines[k]).norm();
  expect_figure({"surface mesh of a circle on 64 cells, length error", "%", 3},
                100 * (length / (2 * std::numbers::pi * radius) - 1), Bound::within, 1.0);

  const MacGrid<3> box = cube<3>(64, 1.0);
  const std::vector<Vec3> triangles = surface_mesh<3>(
      box,
      on_cells(box, [&](const Vec<3>& x) { return (x - Vec<3>::Constant(0.5)).norm() - radius; }));
  double area = 0;
  for (std::size_t k = 0; k < triangles.size(); k += 3)
    area += 0.5 * (triangles[k + 1] - triangles[k]).cross(triangles[k + 2] - triangles[k]).norm();
  const double exact = 4 * std::numbers::pi * radius * radius;
  expect_figure({"surface mesh of a sphere on 64 cells, area error", "%", 3},
                100 * (area / exact - 1), Bound::within, 1.0);
}

}  // namespace
}  // namespace sluice
