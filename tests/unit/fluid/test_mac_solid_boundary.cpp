// The grid model's solids (fluid/mac/solid_boundary.hpp): each face's open fraction is the part
// of its control volume, from one cell centre to the next, outside the solid, so a body's face
// lying across a cell opens the faces around it in proportion to where it lies.
#include <gtest/gtest.h>

#include <string>

#include "sluice/fluid/mac/solid_boundary.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/sim/rigid_bodies.hpp"

namespace sluice {
namespace {

// A 2D tank of 0.1 m cells, 2.0 x 1.0 m, with a held box 0.8 m wide whose underside is at
// `underside` (its top at 0.8 m): a body, or with `as_wall` a wall.
io::CaseConfig held_box(double underside, bool as_wall = false) {
  const double height = 0.8 - underside;
  const std::string box =
      as_wall ? "  - {type: box, min: [0.6, " + std::to_string(underside) + "], max: [1.4, 0.8]}\n"
              : "bodies:\n  - {shape: box, size: [0.8, " + std::to_string(height) +
                    "], density: 500, position: [1.0, " + std::to_string(underside + 0.5 * height) +
                    "], motion: fixed}\n";
  return io::parse_case(
      "dimension: 2\nspacing: 0.1\ndomain: {min: [0, 0], max: [2.0, 1.0]}\nend_time: 1\n"
      "output_interval: 1\nmodel: {name: mac, cell_size: 0.1}\n"
      "fluid:\n  blocks:\n    - {min: [0, 0], max: [2.0, 0.9]}\n"
      "walls:\n  - {type: tank, min: [0, 0], max: [2.0, 1.0], open: [z+]}\n" +
          box,
      "held_box.yaml");
}

// The open fraction of the horizontal face at height z under the box's middle (x = 1.05).
Real open_under_the_box(const SolidBoundary<2>& solid, const MacGrid<2>& grid, double z) {
  const Lattice<2> faces = grid.face_lattice(1);
  const GridIndex<2> c{static_cast<int>(1.0 / grid.h), static_cast<int>(z / grid.h + 0.5)};
  return solid.faces().open[1][faces.index(c)];
}

TEST(MacSolidBoundary, AFaceOpensInProportionToTheSolidInItsControlVolume) {
  MacGrid<2> grid;
  grid.cells = {20, 10};
  grid.h = 0.1;
  // Underside at 0.42: the face at 0.4 (control volume 0.35-0.45) is 70 % open, the face at
  // 0.5 (0.45-0.55) closed, the face at 0.3 (0.25-0.35) open. Area fractions would give 1, 0, 1,
  // the same as for an underside anywhere in 0.4-0.45.
  for (const auto& [underside, at_04] :
       {std::pair{0.42, 0.7}, std::pair{0.38, 0.3}, std::pair{0.45, 1.0}, std::pair{0.35, 0.0}}) {
    const RigidBodies bodies(held_box(underside));
    const SolidBoundary<2> solid(grid, bodies);
    EXPECT_NEAR(open_under_the_box(solid, grid, 0.4), at_04, 1e-9) << "underside " << underside;
    EXPECT_NEAR(open_under_the_box(solid, grid, 0.5), 0.0, 1e-12);
    EXPECT_NEAR(open_under_the_box(solid, grid, 0.3), 1.0, 1e-12);
  }
}

// Beside a moving body a face open by less than 5 % is closed (the body's swept volume would
// leave through it at more than 20 times the body's speed); beside a body at rest or a wall,
// which sweep nothing, it keeps its fraction.
TEST(MacSolidBoundary, AFaceAllButClosedByAMovingBodyIsClosed) {
  MacGrid<2> grid;
  grid.cells = {20, 10};
  grid.h = 0.1;
  for (const auto& [underside, at_04] : {std::pair{0.352, 0.0}, std::pair{0.357, 0.07}}) {
    const RigidBodies bodies(held_box(underside));
    SolidBoundary<2> solid(grid, bodies);
    EXPECT_NEAR(open_under_the_box(solid, grid, 0.4), (underside - 0.35) / 0.1, 1e-9) << "at rest";
    std::vector<BodyKinematics> moving = bodies.motion();
    moving[0].velocity.x() = 0.1;
    solid.place_bodies(moving);
    EXPECT_NEAR(open_under_the_box(solid, grid, 0.4), at_04, 1e-9) << "underside " << underside;
  }
  const RigidBodies walls(held_box(0.352, true));
  EXPECT_NEAR(open_under_the_box(SolidBoundary<2>(grid, walls), grid, 0.4), 0.02, 1e-9);
}

}  // namespace
}  // namespace sluice
