// Fluid particles are kept out of the walls' solids (fluid/wall_surfaces.hpp and the particle
// base's neighbour stage): which points lie in a wall, and a particle pushed into the floor is
// put back on its surface without its velocity into the floor.
#include <gtest/gtest.h>

#include "sluice/fluid/particle_fluid.hpp"
#include "sluice/fluid/wall_surfaces.hpp"
#include "sluice/sim/simulation.hpp"

namespace sluice {
namespace {

TEST(WallSurfaces, TankSidesBoxesAndPlanesHaveTheirSolids) {
  const io::CaseConfig c = io::parse_case(
      "dimension: 3\nspacing: 0.1\ndomain: {min: [0, 0, 0], max: [2, 1, 2]}\nend_time: 1\n"
      "output_interval: 0.1\nfluid:\n  blocks:\n    - {min: [0, 0, 0], max: [0.5, 1, 0.5]}\n"
      "walls:\n  - {type: tank, min: [0, 0, 0], max: [2, 1, 1], open: [z+, x+]}\n"
      "  - {type: box, min: [1, 0, 0], max: [1.2, 1, 0.3]}\n"
      "  - {type: plane, point: [0, 0, 0.05], normal: [0, 0, 1]}\n"
      "model: {name: wcsph}\n",
      "walls.yaml");
  const WallSurfaces solids(c.walls, 3, 0.2);
  EXPECT_FALSE(solids.contains(Vec3(0.5, 0.5, 0.5)));
  EXPECT_TRUE(solids.contains(Vec3(-0.01, 0.5, 0.5)));  // behind x-
  EXPECT_FALSE(solids.contains(Vec3(2.5, 0.5, 0.5)));   // x+ is open
  EXPECT_FALSE(solids.contains(Vec3(0.5, 0.5, 1.5)));   // z+ is open
  EXPECT_TRUE(solids.contains(Vec3(0.5, 1.01, 0.5)));   // behind y+
  EXPECT_TRUE(solids.contains(Vec3(1.1, 0.5, 0.2)));    // in the box
  EXPECT_FALSE(solids.contains(Vec3(1.1, 0.5, 0.35)));  // above it
  EXPECT_TRUE(solids.contains(Vec3(0.5, 0.5, 0.04)));   // under the plane
}

TEST(WallSurfaces, PutBackOnTheNearestFaceOfTheDeepestWallWithinTheBand) {
  const io::CaseConfig c = io::parse_case(
      "dimension: 3\nspacing: 0.1\ndomain: {min: [0, 0, 0], max: [2, 1, 2]}\nend_time: 1\n"
      "output_interval: 0.1\nfluid:\n  blocks:\n    - {min: [0, 0, 0], max: [0.5, 1, 0.5]}\n"
      "walls:\n  - {type: tank, min: [0, 0, 0], max: [2, 1, 1], open: [z+]}\n"
      "  - {type: box, min: [1, 0, 0], max: [1.2, 1, 0.3]}\n"
      "model: {name: wcsph}\n",
      "walls.yaml");
  const WallSurfaces walls(c.walls, 3, 0.2);
  // 0.02 under the box's top, 0.08 from its left face: onto the top, the downward speed gone.
  double x[3] = {1.08, 0.5, 0.28}, v[3] = {0.5, 0.1, -2.0};
  keep_out_of_wall_solids<3>(walls.view(), x, v);
  EXPECT_DOUBLE_EQ(x[0], 1.08);
  EXPECT_DOUBLE_EQ(x[2], 0.3);
  EXPECT_DOUBLE_EQ(v[0], 0.5);
  EXPECT_DOUBLE_EQ(v[2], 0.0);
  // In a corner, 0.05 behind the x- side and 0.01 under the floor: back through the side it is
  // deeper behind; a velocity out of the wall is kept.
  double y[3] = {-0.05, 0.5, -0.01}, w[3] = {1.0, 0, 0};
  keep_out_of_wall_solids<3>(walls.view(), y, w);
  EXPECT_DOUBLE_EQ(y[0], 0.0);
  EXPECT_DOUBLE_EQ(y[2], -0.01);
  EXPECT_DOUBLE_EQ(w[0], 1.0);
  // Deeper than the walls' layers: left where it is.
  double z[3] = {0.5, 0.5, -0.3}, u[3] = {0, 0, -1.0};
  keep_out_of_wall_solids<3>(walls.view(), z, u);
  EXPECT_DOUBLE_EQ(z[2], -0.3);
  EXPECT_DOUBLE_EQ(u[2], -1.0);
}

TEST(WallContainment, AParticleInTheFloorIsPutBackOnItsSurface) {
  const io::CaseConfig c = io::parse_case(
      "dimension: 2\nspacing: 0.02\ndomain: {min: [0, 0], max: [0.4, 0.4]}\nend_time: 1\n"
      "output_interval: 0.1\nfluid:\n  blocks:\n    - {min: [0, 0], max: [0.4, 0.1]}\n"
      "walls:\n  - {type: tank, min: [0, 0], max: [0.4, 0.4], open: [z+]}\n"
      "model: {name: wcsph}\n",
      "floor.yaml");
  Simulation<2> sim(c);
  auto& fluid = dynamic_cast<ParticleFluid<2>&>(sim.fluid());
  auto& ps = fluid.state().particles;
  std::size_t pushed = ps.size();
  for (std::size_t i = 0; i < ps.size() && pushed == ps.size(); ++i) {
    if (ps.is_fluid(i) && ps.position[i][0] > 0.15 && ps.position[i][1] < 0.015) pushed = i;
  }
  ASSERT_LT(pushed, ps.size());
  ps.position[pushed][1] = -0.012;  // within the floor's particle layers
  ps.velocity[pushed] = Vec<2>(0.3, -1.0);
  sim.step(1.0);
  int below = 0, on_floor = 0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (!ps.is_fluid(i)) continue;
    below += ps.position[i][1] < 0;
    if (ps.position[i][1] != 0) continue;
    ++on_floor;
    // Its 1 m/s into the floor is gone from the end of the step too (the second half kick
    // builds on the half-step velocity); what is left is at most the step's own kick.
    EXPECT_GT(ps.velocity[i][1], -0.1);
    EXPECT_NEAR(ps.velocity[i][0], 0.3, 0.05);  // along the floor, kept
  }
  EXPECT_EQ(below, 0);
  EXPECT_EQ(on_floor, 1);
}

}  // namespace
}  // namespace sluice

namespace sluice {
namespace {

// A granular fluid's spheres meet the walls' surfaces (granular/sphere_walls.hpp), so it has
// no wall particles; its walls still keep the fluid out of them, as a particle model's do.
TEST(WallContainment, SpheresMeetTheWallsSurfacesWithoutWallParticles) {
  auto tank = [](const std::string& model) {
    return io::parse_case(
        "dimension: 2\nspacing: 0.02\ndomain: {min: [-0.1, -0.1], max: [0.5, 0.4]}\n"
        "end_time: 1\noutput_interval: 0.1\n"
        "fluid:\n  blocks:\n    - {min: [-0.05, -0.05], max: [0.45, 0.1]}\n"
        "walls:\n  - {type: tank, min: [0, 0], max: [0.4, 0.4], open: [z+]}\n"
        "model: {name: " +
            model + "}\n",
        "tank.yaml");
  };
  const Simulation<2> spheres(tank("granular")), particles(tank("wcsph"));
  const FluidSize with_surfaces = spheres.fluid().observation().size();
  const FluidSize with_layers = particles.fluid().observation().size();
  EXPECT_EQ(with_surfaces.wall, 0u);
  EXPECT_GT(with_layers.wall, 0u);
  EXPECT_EQ(with_surfaces.fluid, with_layers.fluid);
}

}  // namespace
}  // namespace sluice
