// The MPS pressure equation (fluid/mps/pressure_equation.hpp) on a square block of particles
// whose outer ring is the free surface: the rows it assembles, and the artificial
// compressibility with and without the last pressure; and on a closed box of still water,
// whose hydrostatic pressure it must keep.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "mps_lattice.hpp"
#include "sluice/fluid/mps/pressure_equation.hpp"

namespace sluice {
namespace {

constexpr double kSpacing = 0.02;
constexpr int kHalfWidth = 6;

// A still block compressed at a uniform rate: div u* = -1/s everywhere, n* = n0, the outer
// two rings on the free surface.
struct CompressedBlock {
  MpsTestLattice<2> lattice{kHalfWidth, kSpacing, 2.1 * kSpacing};
  MpsLatticeConstants constants = full_lattice_constants<2>(kSpacing, 2.1 * kSpacing);
  std::vector<Vec<2>> velocity;
  std::vector<Real> number_density;
  std::vector<std::int32_t> surface;
  std::vector<std::uint8_t> active;

  CompressedBlock() {
    const Vec<2> centre = lattice.x[lattice.centre];
    for (const Vec<2>& x : lattice.x) {
      velocity.push_back(-0.5 * (x - centre));
      number_density.push_back(constants.n0);
      const Vec<2> d = (x - centre) / kSpacing;
      surface.push_back(std::max(std::abs(d[0]), std::abs(d[1])) > kHalfWidth - 2 + 0.5 ? 1 : 0);
      active.push_back(1);
    }
  }

  // Solves with `alpha` from the last pressure `pressure`, which it overwrites.
  PressureEquationReport solve(double alpha, bool memory, std::vector<Real>& pressure) const {
    PressureEquation<2> equation("cg_diagonal", SolverSettings{1e-12, 1000});
    PressureEquationInputs<2> in{
        MpsOperators<2>(lattice.x, lattice.neighbours, MpsWeight{2.1 * kSpacing}, constants),
        lattice.x.size(),
        velocity.data(),
        number_density.data(),
        surface.data(),
        active.data(),
        pressure.data()};
    in.dt = 1e-3;
    in.density = 1000;
    in.relaxation = 0;
    in.compressibility = alpha;
    in.pressure_memory = memory;
    equation.assemble(in);
    EXPECT_TRUE(equation.solve(pressure));
    return equation.report();
  }
};

TEST(MpsPressureEquation, RowsForTheInnerParticlesOnly) {
  const CompressedBlock block;
  std::vector<Real> pressure(block.lattice.x.size(), 0.0);
  const PressureEquationReport report = block.solve(0, true, pressure);
  const int inner = 2 * (kHalfWidth - 2) + 1;
  EXPECT_EQ(report.unknowns, static_cast<std::size_t>(inner * inner));
  for (std::size_t i = 0; i < pressure.size(); ++i) {
    if (block.surface[i]) {
      EXPECT_EQ(pressure[i], 0.0);
    }
  }
  // Compression raises the pressure, most at the centre.
  for (Real p : pressure) EXPECT_LE(p, pressure[block.lattice.centre]);
  EXPECT_GT(pressure[block.lattice.centre], 0.0);
}

// The pressure of the incompressible solve, given back as the last pressure, is kept by the
// rate form at any alpha (the fluid is not asked to compress further), and lowered by Ikeda's
// form, which asks for alpha p of compression on top of the one already there.
TEST(MpsPressureEquation, ArtificialCompressibilityKeepsTheLastPressure) {
  const CompressedBlock block;
  std::vector<Real> incompressible(block.lattice.x.size(), 0.0);
  block.solve(0, true, incompressible);
  const double alpha = 1e-7;  // 1/Pa: comparable with the Laplacian's l0^-2 at dt = 1 ms

  std::vector<Real> rate = incompressible;
  block.solve(alpha, true, rate);
  std::vector<Real> ikeda = incompressible;
  block.solve(alpha, false, ikeda);
  const std::size_t c = block.lattice.centre;
  EXPECT_NEAR(rate[c], incompressible[c], 1e-8 * incompressible[c]);
  EXPECT_LT(ikeda[c], 0.9 * incompressible[c]);
}

// Still water in a closed box: two rings of wall particles (a first layer and a dummy one)
// around the fluid, gravity in u* = g dt on the fluid, the walls at rest, and the last pressure
// hydrostatic. The solve must give that pressure back. With the walls' pressures extrapolated
// from the fluid it does, to the solver's tolerance: the Laplacian sees a linear field on full
// support, and with the walls carried on by dt g in the divergence, a uniform u* has none. With
// the first wall layer in rows of its own (Koshizuka & Oka 1996), it does not: those rows'
// divergence source is about half what their one-sided Laplacian needs.
TEST(MpsPressureEquation, ExtrapolatedWallsKeepAClosedBoxHydrostatic) {
  constexpr int kHalf = 7;
  const MpsTestLattice<2> lattice{kHalf, kSpacing, 2.1 * kSpacing};
  const MpsLatticeConstants constants = full_lattice_constants<2>(kSpacing, 2.1 * kSpacing);
  const double g = 9.81, rho = 1000, dt = 1e-3;
  const std::size_t n = lattice.x.size();
  const Vec<2> centre = lattice.x[lattice.centre];
  std::vector<Vec<2>> velocity(n), carried(n), wall_gravity(n, Vec<2>(0, -g));
  std::vector<Real> number_density(n, constants.n0), hydrostatic(n);
  std::vector<std::int32_t> surface(n, 0);
  std::vector<std::uint8_t> wall(n), first_layer(n), everything(n, 1), fluid_and_first(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec<2> d = (lattice.x[i] - centre) / kSpacing;
    const double ring = std::max(std::abs(d[0]), std::abs(d[1]));
    wall[i] = ring > kHalf - 2 + 0.5 ? 1 : 0;
    first_layer[i] = wall[i] && ring < kHalf - 0.5 ? 1 : 0;
    fluid_and_first[i] = !wall[i] || first_layer[i];
    velocity[i] = wall[i] ? Vec<2>::Zero() : Vec<2>(0, -g * dt);
    carried[i] = Vec<2>(0, -g * dt);  // u_w + dt (g - a_w) on the walls: u* everywhere
    hydrostatic[i] = rho * g * (1.0 - lattice.x[i][1]);
  }
  const auto solve = [&](bool extrapolated) {
    PressureEquation<2> equation(extrapolated ? "bicgstab_diagonal" : "cg_diagonal",
                                 SolverSettings{1e-12, 2000});
    PressureEquationInputs<2> in{
        MpsOperators<2>(lattice.x, lattice.neighbours, MpsWeight{2.1 * kSpacing}, constants),
        lattice.x.size(),
        extrapolated ? carried.data() : velocity.data(),
        number_density.data(),
        surface.data(),
        extrapolated ? everything.data() : fluid_and_first.data(),
        hydrostatic.data()};
    in.dt = dt;
    in.density = rho;
    in.relaxation = 0;
    in.compressibility = 1e-7;  // 1/Pa: fixes the level of a box with no free surface
    if (extrapolated) {
      in.extrapolated = wall.data();
      in.wall_gravity = wall_gravity.data();
    }
    equation.assemble(in);
    std::vector<Real> pressure(n, 0.0);  // solved from zero, not from the answer
    EXPECT_TRUE(equation.solve(pressure));
    double worst = 0;  // the largest error on the fluid, relative to rho g times the box's height
    for (std::size_t i = 0; i < n; ++i) {
      if (!wall[i]) worst = std::max(worst, std::abs(pressure[i] - hydrostatic[i]));
    }
    return worst / (rho * g * (2 * kHalf) * kSpacing);
  };
  const double extrapolated = solve(true), own_rows = solve(false);
  std::printf("closed box: largest pressure error %.2e (extrapolated walls), %.2e (own rows)\n",
              extrapolated, own_rows);
  EXPECT_LT(extrapolated, 1e-6);
  EXPECT_GT(own_rows, 1e-2);
}

}  // namespace
}  // namespace sluice
