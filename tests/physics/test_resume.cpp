// Resuming is exact: for every model (and bodies alone, with joints, penalty contact and
// complementarity contact), a run of T and a run of T/2 resumed to T write the same files,
// byte for byte: frames, series, probes, bodies' CSVs and the final checkpoint (the whole
// state). T/2 is a multiple of the output intervals, where both runs end a step.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "physics_support.hpp"
#include "sluice/sim/checkpoints.hpp"
#include "sluice/sim/runner.hpp"
#include "support/scratch_dir.hpp"

namespace sluice {
namespace {

namespace fs = std::filesystem;
using test_support::ScratchDir;

struct ResumeCase {
  const char* label;
  const char* file;
  double end;
  std::vector<std::string> overrides;
};

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every file of an output directory by its relative path; of the checkpoints, the newest.
std::map<std::string, std::string> output_files(const fs::path& out) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(out)) {
    if (!entry.is_regular_file()) continue;
    const std::string relative = fs::relative(entry.path(), out).string();
    if (relative.starts_with("checkpoints/")) continue;
    files[relative] = read_bytes(entry.path());
  }
  const std::vector<std::string> checkpoints = CheckpointFolder(out.string()).files();
  if (!checkpoints.empty()) files["newest checkpoint"] = read_bytes(checkpoints.front());
  return files;
}

class Resume : public ::testing::TestWithParam<ResumeCase> {};

TEST_P(Resume, RunOfTEqualsRunOfHalfTResumed) {
  const ResumeCase& c = GetParam();
  std::vector<std::string> overrides = c.overrides;
  overrides.push_back("checkpoint_interval=" + std::to_string(c.end / 4));
  const io::CaseConfig config = testing::load_case(c.file, overrides);
  ScratchDir scratch("resume");
  RunOptions options;
  options.quiet = true;

  options.out_dir = (scratch / "whole").string();
  options.end_time = c.end;
  const RunSummary whole = run_case(config, options);

  options.out_dir = (scratch / "halves").string();
  options.end_time = c.end / 2;
  const RunSummary first_half = run_case(config, options);
  options.end_time = c.end;
  options.resume = true;
  const RunSummary second_half = run_case(config, options);

  EXPECT_GT(first_half.steps, 0);
  EXPECT_EQ(first_half.steps + second_half.steps, whole.steps);
  // Where half the end and an output differ by rounding (1.4 / 2 and 35 x 0.02 s), the output's.
  EXPECT_NEAR(second_half.start_time, c.end / 2, 1e-12 * c.end);
  EXPECT_EQ(whole.final_probes, second_half.final_probes);
  const auto expected = output_files(scratch / "whole");
  const auto resumed = output_files(scratch / "halves");
  ASSERT_GT(expected.count("newest checkpoint"), 0u);
  for (const auto& [name, bytes] : expected) {
    ASSERT_GT(resumed.count(name), 0u) << name << " missing after resuming";
    EXPECT_TRUE(resumed.at(name) == bytes) << name << " differs after resuming";
  }
  EXPECT_EQ(resumed.size(), expected.size());
}

const ResumeCase kCases[] = {
    {"wcsph", "dam_break_2d.yaml", 0.2, {"spacing=0.05"}},
    {"mps", "dam_break_2d_mps.yaml", 0.2, {"spacing=0.05"}},
    {"penalty_sph_free_grains", "free_bed_2d.yaml", 0.1, {"output_interval=0.025"}},
    {"constraint", "dam_break_2d.yaml", 0.2, {"spacing=0.05", "model.name=constraint"}},
    {"granular", "granular_pool_2d.yaml", 0.2, {}},
    {"granular_with_a_body", "granular_floating_box_2d.yaml", 0.2, {}},
    {"mac_without_volume_correction",
     "dam_break_2d.yaml",
     0.2,
     {"spacing=0.05", "model={name: mac, cell_size: 0.05, volume_correction: false}"}},
    // The volume correction: the water it holds, what it gave back, and the shift the markers
    // have yet to follow (past the first impact, where the level set loses water).
    {"mac", "dam_break_2d.yaml", 1.4, {"spacing=0.05", "model={name: mac}"}},
    {"wcsph_bodies_in_contact", "subcycling_2d.yaml", 0.2, {"spacing=0.02"}},
    // The device run (here on the host's threads): its particles written and read back.
    {"wcsph_device_bodies_in_contact",
     "subcycling_2d.yaml",
     0.2,
     {"spacing=0.02", "model.device=emulated"}},
    // mps on its device: the neighbour list the next prediction reads, written and read back;
    // the particles keep the order and cells of their last sort, though they have moved since.
    {"mps_device_body", "floating_box_2d.yaml", 0.2, {"model={name: mps, device: emulated}"}},
    // penalty-sph on its device: the walls gathered again there after reading.
    {"penalty_sph_device_body",
     "floating_box_2d.yaml",
     0.2,
     {"model={name: penalty-sph, device: emulated}"}},
    // A paddle's active absorption: what it has added to the signal, written and read back.
    {"mac_absorbing_paddle",
     "paddle_absorption_2d.yaml",
     1.0,
     {"spacing=0.04", "output_interval=0.25"}},
    // Open boundaries' buffers and a transport velocity's background acceleration.
    {"wcsph_transport_velocity_channel",
     "cylinder_channel_wcsph_2d.yaml",
     0.4,
     {"spacing=0.02", "output_interval=0.1"}},
    {"wcsph_3d_cubes", "dam_break_cubes_3.yaml", 0.04, {"spacing=0.05"}},
    {"bodies_alone_joints", "pendulum.yaml", 0.4, {}},
    {"bodies_alone_complementarity", "sphere_stack.yaml", 0.4, {}},
};

INSTANTIATE_TEST_SUITE_P(EveryModel, Resume, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.label); });

}  // namespace
}  // namespace sluice
