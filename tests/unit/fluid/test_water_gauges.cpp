// The water-height gauge reads the top of the water standing on the bed, in every model: a sheet
// thrown up above the water does not count (it did: F3's gauge in front of the obstacle read the
// tank's roof under `constraint`'s spray).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sluice/fluid/water_column.hpp"
#include "sluice/sim/simulation.hpp"

namespace sluice {
namespace {

std::ptrdiff_t top_of(const std::vector<int>& water, std::size_t bridged = 0) {
  return top_of_lowest_water(
      water.size(), [&](std::size_t k) { return water[k] != 0; }, bridged);
}

TEST(WaterColumn, TopOfTheLowestRunOfWater) {
  EXPECT_EQ(top_of({1, 1, 1, 0, 0}), 2);
  EXPECT_EQ(top_of({1, 1, 0, 1, 1, 0}), 1);  // the sheet above the gap is spray
  EXPECT_EQ(top_of({0, 1, 1, 0, 1}), 2);     // a dry sample at the floor (the wall halves the sum)
  EXPECT_EQ(top_of({1, 1, 1}), 2);           // full to the top
  EXPECT_EQ(top_of({0, 0, 0}), -1);          // dry
  EXPECT_EQ(top_of({}), -1);
  EXPECT_EQ(top_of({1, 0, 0, 1, 1, 0, 0, 0, 1}, 2), 4);  // a gap of two bridged, not of three
  EXPECT_EQ(top_of({1, 0, 0}, 2), 0);
}

// A 2D tank 0.4 m wide with water 0.2 m deep and a sheet four spacings thick from 0.40 to 0.48 m.
io::CaseConfig tank_with_a_sheet(const std::string& model) {
  return io::parse_case(
      "dimension: 2\nspacing: 0.02\ndomain: {min: [0, 0], max: [0.4, 0.6]}\n"
      "end_time: 0.1\noutput_interval: 0.1\n"
      "fluid:\n  blocks:\n    - {min: [0, 0], max: [0.4, 0.2]}\n"
      "    - {min: [0, 0.4], max: [0.4, 0.48]}\n"
      "walls:\n  - {type: tank, min: [0, 0], max: [0.4, 0.6], open: [z+]}\n"
      "model: {name: " +
          model + "}\n",
      "sheet.yaml");
}

class WaterGauge : public ::testing::TestWithParam<std::string> {};

TEST_P(WaterGauge, ReadsTheWaterOnTheBedNotTheSheetAboveIt) {
  Simulation<2> sim(tank_with_a_sheet(GetParam()));
  const double height = sim.fluid().observation().water_height_at(Vec3(0.2, 0, 0));
  EXPECT_NEAR(height, 0.2, 0.02);  // within a spacing; the sheet's top would read 0.48
}

INSTANTIATE_TEST_SUITE_P(EveryModel, WaterGauge,
                         ::testing::Values("wcsph", "mps", "penalty-sph", "constraint", "granular",
                                           "mac"),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

}  // namespace
}  // namespace sluice
