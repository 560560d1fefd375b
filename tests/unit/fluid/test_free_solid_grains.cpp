// Penalty-sph's free solid layers: each lattice site of a free layer becomes a sphere body of
// the layer's spacing, added after the case's own bodies; a fixed layer adds none.
#include <gtest/gtest.h>

#include "sluice/fluid/penalty_sph/penalty_sph_parameters.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/models/shipped_models.hpp"

namespace sluice {
namespace {

io::CaseConfig bed_case() {
  return io::parse_case(R"(
name: bed
dimension: 3
spacing: 0.005
domain: {min: [0, 0, 0], max: [0.02, 0.02, 0.1]}
end_time: 0.1
output_interval: 0.1
fluid:
  blocks:
    - {min: [0, 0, 0.05], max: [0.02, 0.02, 0.06]}
walls:
  - {type: tank, min: [0, 0, 0], max: [0.02, 0.02, 0.1], open: [z+]}
bodies:
  - {name: lid, shape: box, size: [0.02, 0.02, 0.005], density: 500, position: [0.01, 0.01, 0.08]}
model:
  name: penalty-sph
  solids:
    - {min: [0, 0, 0], max: [0.02, 0.02, 0.01], spacing_ratio: 2, density: 2650, free: true,
       material: {friction: 0.7}}
    - {min: [0, 0, 0.02], max: [0.02, 0.02, 0.025], spacing_ratio: 1}
)",
                        "bed.yaml");
}

TEST(FreeSolidGrains, OneSphereBodyPerSiteOfAFreeLayer) {
  const std::vector<io::BodyConfig> grains = free_solid_grains(bed_case());
  ASSERT_EQ(grains.size(), 4u);  // 2 x 2 x 1 sites of 0.01 m; the fixed layer adds none
  for (std::size_t n = 0; n < grains.size(); ++n) {
    const io::BodyConfig& g = grains[n];
    EXPECT_EQ(g.name, "solids0_grain" + std::to_string(n));
    EXPECT_EQ(g.shape, io::BodyShape::kSphere);
    EXPECT_DOUBLE_EQ(g.radius, 0.005);
    EXPECT_DOUBLE_EQ(g.density, 2650);
    EXPECT_DOUBLE_EQ(g.material.friction, 0.7);
    EXPECT_TRUE(g.seen_as_one_particle);
    EXPECT_DOUBLE_EQ(g.position.z(), 0.005);
    EXPECT_EQ(g.motion, io::BodyMotion::kFree);
  }
  EXPECT_EQ(grains[0].position, Vec3(0.005, 0.005, 0.005));
  EXPECT_EQ(grains[3].position, Vec3(0.015, 0.015, 0.005));
}

TEST(FreeSolidGrains, TheModelAddsThemAfterTheCaseBodies) {
  const io::CaseConfig config = shipped_models<3>().prepared(bed_case());
  ASSERT_EQ(config.bodies.size(), 5u);
  EXPECT_EQ(config.bodies[0].name, "lid");
  EXPECT_FALSE(config.bodies[0].seen_as_one_particle);
  EXPECT_EQ(config.bodies[4].name, "solids0_grain3");
  // Another model adds nothing.
  io::CaseConfig wcsph = bed_case();
  wcsph.model_name = "wcsph";
  EXPECT_EQ(shipped_models<3>().prepared(wcsph).bodies.size(), 1u);
}

}  // namespace
}  // namespace sluice
