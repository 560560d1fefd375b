// The MPS device run (issue 41) on the host's threads (`model.device: emulated`): the loop
// bodies the CPU path runs, in the same order, over the device's own copy of the particles,
// with its own sort, scans, neighbour list and numbering of the pressure's unknowns, and the
// CPU's sparse solver on the rows it assembles. It must give the CPU's answer bit for bit in
// F1, F2 and B1, and on a 3D vehicle with its parts on joints.
#include <gtest/gtest.h>

#include "device_run_support.hpp"

namespace sluice {
namespace {

using testing::expect_same_bits;

TEST(MpsDevice, EmulatedRunIsTheCpuRunBitForBit) {
  expect_same_bits<2>("hydrostatic_2d_mps.yaml", {"end_time=0.3"}, 0.3);    // F1
  expect_same_bits<2>("dam_break_2d_mps.yaml", {}, 0.3);                    // F2
  expect_same_bits<2>("floating_box_2d.yaml", {"model={name: mps}"}, 0.3);  // B1
  // The explicit variant, and the walls' first layer solved rather than extrapolated.
  expect_same_bits<2>("dam_break_2d_mps.yaml", {"model.variant=explicit"}, 0.1);
  expect_same_bits<2>("floating_box_2d.yaml", {"model={name: mps, wall_pressure: solved}"}, 0.2);
  // 3D, a vehicle on joints in still water (B5's parked vehicle).
  expect_same_bits<3>("parked_vehicle.yaml", {"model={name: mps}"}, 0.04);
}

TEST(MpsDevice, OnlyTheCpuAndTheEmulatedDeviceAreOffered) {
  try {
    Simulation<2> sim(testing::load_case("dam_break_2d_mps.yaml", {"model.device=gpu"}));
    FAIL() << "mps started on a GPU it has no run for";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("model.device"), std::string::npos) << message;
    EXPECT_NE(message.find("emulated"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace sluice
