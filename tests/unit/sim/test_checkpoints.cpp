// OUT/checkpoints/: the newest two kept; resuming takes the newest that reads back whole (no
// later than a given step, where ranks agree on one) and refuses one of another case, model or
// version.
#include "sluice/sim/checkpoints.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "sluice/core/errors.hpp"
#include "support/scratch_dir.hpp"

namespace sluice {
namespace {

using test_support::ScratchDir;

io::CaseConfig small_case(const std::vector<std::string>& overrides = {}) {
  return io::read_case(std::string(SLUICE_SOURCE_DIR) + "/cases/dam_break_2d.yaml", overrides);
}

io::CheckpointHeader at_step(io::CheckpointHeader h, long step) {
  h.step = step;
  h.time = 0.001 * double(step);
  return h;
}

std::string file_name(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

TEST(CheckpointFolder, KeepsTheNewestTwoInStepOrder) {
  ScratchDir out("checkpoints");
  const CheckpointFolder folder(out.path().string());
  const io::CheckpointHeader h = checkpoint_header(small_case(), 2);
  for (long step : {9, 10, 100, 1000}) folder.write(at_step(h, step), "state");
  std::ofstream(folder.path() + "/step_0000002000.ckpt.tmp") << "left by a kill";
  folder.write(at_step(h, 1001), "state");
  const std::vector<std::string> files = folder.files();
  ASSERT_EQ(files.size(), kCheckpointsKept);
  EXPECT_EQ(file_name(files[0]), "step_0000001001.ckpt");
  EXPECT_EQ(file_name(files[1]), "step_0000001000.ckpt");
  EXPECT_FALSE(std::filesystem::exists(folder.path() + "/step_0000002000.ckpt.tmp"));
}

TEST(CheckpointFolder, DamagedNewestIsSkippedWithAWarning) {
  ScratchDir out("checkpoints");
  const CheckpointFolder folder(out.path().string());
  const io::CheckpointHeader h = checkpoint_header(small_case(), 2);
  folder.write(at_step(h, 10), "older");
  folder.write(at_step(h, 20), "newer");
  std::filesystem::resize_file(folder.files()[0], 30);  // cut short, as by a full disk
  std::vector<std::string> warnings;
  const io::Checkpoint c =
      newest_checkpoint(folder, h, [&](const std::string& w) { warnings.push_back(w); });
  EXPECT_EQ(c.state, "older");
  EXPECT_EQ(c.header.step, 10);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("skipping the checkpoint"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("step_0000000020.ckpt"), std::string::npos) << warnings[0];
}

// On several ranks the resume looks below a step that one rank lacks (its write cut short).
TEST(CheckpointFolder, NewestNoLaterThanAStep) {
  ScratchDir out("checkpoints");
  const CheckpointFolder folder(out.path().string());
  const io::CheckpointHeader h = checkpoint_header(small_case(), 2);
  folder.write(at_step(h, 10), "older");
  folder.write(at_step(h, 20), "newer");
  const auto no_warning = [](const std::string& w) { ADD_FAILURE() << w; };
  EXPECT_EQ(newest_checkpoint(folder, h, no_warning, 20).state, "newer");
  EXPECT_EQ(newest_checkpoint(folder, h, no_warning, 19).state, "older");
  EXPECT_EQ(newest_checkpoint(folder, h, no_warning, 10).header.step, 10);
  EXPECT_THROW(newest_checkpoint(folder, h, no_warning, 9), InputError);
  // One rank alone: its own newest.
  EXPECT_EQ(newest_checkpoint_of_every_rank(folder, h, no_warning, Communicator::alone()).state,
            "newer");
}

// A run resumed on another number of ranks reads every writing rank's piece of the newest step
// that all of them hold whole; its own checkpoints, once there, come first.
TEST(CheckpointFolder, PiecesWrittenOnAnotherNumberOfRanks) {
  ScratchDir out("checkpoints");
  const io::CheckpointHeader h = checkpoint_header(small_case(), 2);
  const std::filesystem::path root = out.path() / "checkpoints";
  const auto write_piece = [&](int rank, int ranks, long step) {
    const std::filesystem::path folder = root / fmt::format("rank_{}_of_{}", rank, ranks);
    std::filesystem::create_directories(folder);
    io::write_checkpoint((folder / fmt::format("step_{:010d}.ckpt", step)).string(),
                         at_step(h, step), fmt::format("rank {} step {}", rank, step));
  };
  const CheckpointFolder one_rank(out.path().string());
  const auto no_warning = [](const std::string& w) { ADD_FAILURE() << w; };
  write_piece(0, 2, 10);  // rank 1 holds none yet
  EXPECT_THROW(pieces_written_on_another_count(one_rank, h, no_warning), InputError);
  write_piece(1, 2, 10);
  write_piece(0, 2, 20);  // rank 1's step 20 was cut short
  const std::vector<io::Checkpoint> pieces =
      pieces_written_on_another_count(one_rank, h, no_warning);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(pieces[0].state, "rank 0 step 10");
  EXPECT_EQ(pieces[1].state, "rank 1 step 10");

  write_piece(0, 3, 30);  // a second run's, on 3 ranks
  EXPECT_THROW(pieces_written_on_another_count(one_rank, h, no_warning), InputError);

  one_rank.write(at_step(h, 40), "one rank's own");
  EXPECT_TRUE(pieces_written_on_another_count(one_rank, h, no_warning).empty());
  one_rank.remove_other_counts();
  EXPECT_FALSE(std::filesystem::exists(root / "rank_0_of_2"));
  EXPECT_FALSE(std::filesystem::exists(root / "rank_0_of_3"));
  EXPECT_EQ(newest_checkpoint(one_rank, h, no_warning).state, "one rank's own");
}

// The InputError message of resuming `folder` as `expected` ("" if it resumes).
std::string refusal(const CheckpointFolder& folder, const io::CheckpointHeader& expected) {
  try {
    newest_checkpoint(folder, expected, [](const std::string&) {});
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CheckpointFolder, OtherCaseModelVersionOrSettingsRefused) {
  ScratchDir out("checkpoints");
  const CheckpointFolder folder(out.path().string());
  const io::CheckpointHeader h = checkpoint_header(small_case(), 2);
  folder.write(at_step(h, 10), "state");
  EXPECT_EQ(refusal(folder, h), "");

  // --end and checkpoint_interval may change on resuming; the physics may not.
  EXPECT_EQ(
      refusal(folder, checkpoint_header(small_case({"end_time=5", "checkpoint_interval=1"}), 2)),
      "");
  EXPECT_NE(refusal(folder, checkpoint_header(small_case({"spacing=0.05"}), 2))
                .find("of another version of the case 'dam_break_2d'"),
            std::string::npos);
  EXPECT_NE(refusal(folder, checkpoint_header(small_case({"model.name=mps"}), 2))
                .find("of the model 'wcsph', this case runs 'mps'"),
            std::string::npos);
  EXPECT_NE(refusal(folder, checkpoint_header(small_case({"name=other"}), 2))
                .find("of the 2D case 'dam_break_2d', not of the 2D case 'other'"),
            std::string::npos);
  io::CheckpointHeader newer = h;
  newer.sluice_version = "99.0.0";
  EXPECT_NE(
      refusal(folder, newer).find("of sluice " + h.sluice_version + ", this is sluice 99.0.0"),
      std::string::npos);
}

TEST(CheckpointFolder, NothingToResumeFromIsSaid) {
  ScratchDir out("checkpoints");
  const CheckpointFolder folder(out.path().string());
  EXPECT_NE(refusal(folder, checkpoint_header(small_case(), 2)).find("no checkpoint to resume"),
            std::string::npos);
}

}  // namespace
}  // namespace sluice
