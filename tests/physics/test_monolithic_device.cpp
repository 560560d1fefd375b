// The monolithic models' complementarity solve on the emulated device (issue 41;
// `model.device: emulated`): the rows built on the host, the bodies, the density, viscosity,
// sphere-contact and rigid rows copied to the device each solve and solved there by the
// solver's steps over the copies. It must give the CPU's answer bit for bit in F1's tank, F2
// and B1, for the constraint fluid and the granular one.
#include <gtest/gtest.h>

#include "device_run_support.hpp"

namespace sluice {
namespace {

using testing::expect_same_bits;

TEST(ConstraintDevice, EmulatedRunIsTheCpuRunBitForBit) {
  expect_same_bits<2>("hydrostatic_2d.yaml", {"model={name: constraint}"}, 0.1);  // F1
  expect_same_bits<2>("dam_break_2d.yaml", {"spacing=0.025", "model={name: constraint}"},
                      0.1);                                                        // F2
  expect_same_bits<2>("floating_box_2d.yaml", {"model={name: constraint}"}, 0.3);  // B1
}

TEST(GranularDevice, EmulatedRunIsTheCpuRunBitForBit) {
  expect_same_bits<2>("hydrostatic_2d.yaml", {"model={name: granular}"}, 0.15);               // F1
  expect_same_bits<2>("dam_break_2d.yaml", {"model={name: granular, friction: 0.3}"}, 0.15);  // F2
  expect_same_bits<2>("floating_box_2d.yaml", {"model={name: granular}"}, 0.2);               // B1
}

}  // namespace
}  // namespace sluice
