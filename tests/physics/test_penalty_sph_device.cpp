// The penalty-sph device run (issue 41) on the host's threads (`model.device: emulated`): the
// loop bodies the CPU path runs, over the device's own copy of the particles, with the solids
// gathered, sorted and gridded there, the drift's scratch in bounded lists, and the impulses on
// the bodies summed there in particle order. It must give the CPU's answer bit for bit in F1's
// tank, F2 and B1, and on a 3D vehicle with its parts on joints.
#include <gtest/gtest.h>

#include "device_run_support.hpp"

namespace sluice {
namespace {

using testing::expect_same_bits;

TEST(PenaltySphDevice, EmulatedRunIsTheCpuRunBitForBit) {
  expect_same_bits<2>("hydrostatic_2d.yaml", {"model={name: penalty-sph}"}, 0.3);  // F1
  expect_same_bits<2>("dam_break_2d.yaml", {"spacing=0.025", "model={name: penalty-sph}"},
                      0.3);                                                         // F2
  expect_same_bits<2>("floating_box_2d.yaml", {"model={name: penalty-sph}"}, 0.3);  // B1
  // 3D, a vehicle on joints in still water (B5's parked vehicle).
  expect_same_bits<3>("parked_vehicle.yaml", {"model={name: penalty-sph}"}, 0.03);
}

}  // namespace
}  // namespace sluice
