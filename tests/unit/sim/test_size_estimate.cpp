// The size estimate made before anything is built: an upper bound on the particles (or cells)
// the case builds, not far above them, and a refusal naming `spacing` when it cannot fit.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "sluice/core/errors.hpp"
#include "sluice/fluid/wcsph/wcsph_device_run.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/sim/runner.hpp"
#include "sluice/sim/size_estimate.hpp"

namespace sluice {
namespace {

// The water in a tank (or, with `plane`, on a floor plane), with a box floating on it.
io::CaseConfig tank_case(int dimension, const std::string& model, double spacing,
                         bool plane = false) {
  const std::string box = dimension == 2 ? "[0, 0]" : "[0, 0, 0]";
  const std::string far = dimension == 2 ? "[1.0, 0.6]" : "[1.0, 0.5, 0.6]";
  const std::string water = dimension == 2 ? "[0.4, 0.3]" : "[0.4, 0.5, 0.3]";
  const std::string size = dimension == 2 ? "[0.1, 0.1]" : "[0.1, 0.1, 0.1]";
  const std::string at = dimension == 2 ? "[0.7, 0.1]" : "[0.7, 0.25, 0.1]";
  return io::parse_case(
      fmt::format("dimension: {}\nspacing: {}\ndomain: {{min: {}, max: {}}}\nend_time: 0.1\n"
                  "output_interval: 0.1\nfluid:\n  blocks:\n    - {{min: {}, max: {}}}\n"
                  "walls:\n  - {}\n"
                  "bodies:\n  - {{shape: box, size: {}, density: 500, position: {}}}\n"
                  "model: {{name: {}}}\n",
                  dimension, spacing, box, far, box, water,
                  plane ? fmt::format("{{type: plane, point: {}, normal: {}}}", box,
                                      dimension == 2 ? "[0, 1]" : "[0, 0, 1]")
                        : fmt::format("{{type: tank, min: {}, max: {}, open: [z+]}}", box, far),
                  size, at, model),
      "estimate.yaml");
}

TEST(SizeEstimate, BoundsTheBuiltCountFromAbove) {
  for (int dimension : {2, 3}) {
    for (const std::string model : {"wcsph", "mps", "mac"}) {
      for (const bool plane : {false, true}) {
        if (plane && model == "mac") continue;  // the grid model's walls are its grid's sides
        const io::CaseConfig config = tank_case(dimension, model, 0.05, plane);
        const SizeEstimate estimate = estimate_size(config);
        const CheckSummary built = check_case(config);
        SCOPED_TRACE(fmt::format("{}D {}{}: estimate {}, built {}", dimension, model,
                                 plane ? " on a plane" : "", estimate.elements, built.particles));
        EXPECT_EQ(estimate.element_name, built.element_name);
        EXPECT_GE(estimate.elements, double(built.particles));
        EXPECT_LE(estimate.elements, 2.5 * double(built.particles));
        EXPECT_GT(estimate.bytes, estimate.elements * 100);
      }
    }
  }
}

// Volumes (water, bodies) grow as the spacing to the power -3, wall layers as -2.
TEST(SizeEstimate, AHundredthOfTheSpacingMultipliesTheCountBy1e4To1e6) {
  const double coarse = estimate_size(tank_case(3, "wcsph", 0.05)).elements;
  const double fine = estimate_size(tank_case(3, "wcsph", 0.0005)).elements;
  EXPECT_GT(fine / coarse, 2e4);
  EXPECT_LT(fine / coarse, 1e6);
}

TEST(SizeEstimate, RefusesACaseThatCannotFitAtItsSpacing) {
  const io::CaseConfig config = tank_case(3, "wcsph", 0.0005);
  const SizeEstimate estimate = estimate_size(config);
  EXPECT_NO_THROW(refuse_if_it_cannot_fit(config, estimate, 2 * estimate.bytes));
  try {
    refuse_if_it_cannot_fit(config, estimate, 24e9);
    FAIL() << "not refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "spacing");
    EXPECT_EQ(e.line(), 2);
    EXPECT_NE(std::string(e.what()).find("this machine has 24 GB"), std::string::npos) << e.what();
  }
}

// A case on a GPU: model.device gpu with the wcsph model, and no other.
io::CaseConfig on_device(io::CaseConfig config, const std::string& device) {
  config.model["device"] = device;
  return config;
}

TEST(SizeEstimate, OnlyWcsphWithDeviceGpuRunsOnAGpu) {
  EXPECT_TRUE(runs_on_a_gpu(on_device(tank_case(3, "wcsph", 0.05), "gpu")));
  EXPECT_FALSE(runs_on_a_gpu(tank_case(3, "wcsph", 0.05)));
  EXPECT_FALSE(runs_on_a_gpu(on_device(tank_case(3, "wcsph", 0.05), "emulated")));
  EXPECT_FALSE(runs_on_a_gpu(on_device(tank_case(3, "mps", 0.05), "gpu")));
}

TEST(SizeEstimate, TheEmulatedDeviceAddsItsCopyToTheHostsMemory) {
  for (const char* model : {"wcsph", "mps", "penalty-sph"}) {
    const io::CaseConfig config = tank_case(3, model, 0.01);
    const SizeEstimate cpu = estimate_size(config);
    const SizeEstimate emulated = estimate_size(on_device(config, "emulated"));
    EXPECT_EQ(emulated.elements, cpu.elements) << model;
    const double per_element = (emulated.bytes - cpu.bytes) / cpu.elements;
    EXPECT_GT(per_element, 300) << model;  // the device's fields, at least the host's in bytes
    EXPECT_LT(per_element, 1000) << model;
  }
}

TEST(SizeEstimate, RefusesACaseThatCannotFitInTheGpusFreeMemory) {
  const io::CaseConfig config = on_device(tank_case(3, "wcsph", 0.002), "gpu");
  const SizeEstimate estimate = estimate_size(config);
  const double needed = estimate.elements * wcsph_device_bytes_per_particle(3);
  EXPECT_NO_THROW(refuse_if_the_gpu_cannot_hold(config, estimate, {"Test GPU", 2 * needed}));
  EXPECT_NO_THROW(refuse_if_the_gpu_cannot_hold(config, estimate, {"GPU", 0}));  // unknown
  try {
    refuse_if_the_gpu_cannot_hold(config, estimate, {"Test GPU", needed / 2});
    FAIL() << "not refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "spacing");
    EXPECT_EQ(e.line(), 2);
    const std::string message = e.what();
    EXPECT_NE(
        message.find("GPU's memory; the Test GPU has " + readable_bytes(needed / 2) + " free"),
        std::string::npos)
        << message;
  }
}

TEST(SizeEstimate, ReadableBytes) {
  EXPECT_EQ(readable_bytes(950), "950 B");
  EXPECT_EQ(readable_bytes(2.08e12), "2.08 TB");
}

}  // namespace
}  // namespace sluice
