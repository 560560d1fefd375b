// The checkpoint file: read back whole, and any file cut short or with any byte changed
// recognised as such.
#include "sluice/io/checkpoint_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "sluice/core/build_info.hpp"
#include "support/scratch_dir.hpp"

namespace sluice::io {
namespace {

using test_support::ScratchDir;
using namespace std::string_literals;

CheckpointHeader sample_header() {
  CheckpointHeader h;
  h.sluice_version = sluice_version();
  h.case_name = "dam_break_2d";
  h.model = "wcsph";
  h.dimension = 2;
  h.case_identity = crc32_of("spacing: 0.05");
  h.time = 0.1;
  h.step = 440;
  return h;
}

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// The message of the CheckpointError that reading `path` throws ("" if none).
std::string refusal(const std::filesystem::path& path) {
  try {
    read_checkpoint(path.string());
  } catch (const CheckpointError& e) {
    return e.what();
  }
  return "";
}

TEST(CheckpointFile, ReadsBackHeaderAndStateAndLeavesNoTemporary) {
  ScratchDir dir("checkpoint_file");
  const std::string path = (dir / "a.ckpt").string();
  const std::string state = "\0\1\2 state bytes \xff"s;  // with NULs: not a C string
  write_checkpoint(path, sample_header(), state);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  const Checkpoint c = read_checkpoint(path);
  EXPECT_EQ(c.path, path);
  EXPECT_EQ(c.state, state);
  EXPECT_EQ(c.header.case_name, "dam_break_2d");
  EXPECT_EQ(c.header.model, "wcsph");
  EXPECT_EQ(c.header.dimension, 2);
  EXPECT_EQ(c.header.case_identity, crc32_of("spacing: 0.05"));
  EXPECT_EQ(c.header.time, 0.1);
  EXPECT_EQ(c.header.step, 440);
  EXPECT_EQ(c.header.sluice_version, sluice_version());
}

// zlib's CRC-32 is the standard one (the check value of "123456789").
TEST(CheckpointFile, ChecksumIsCrc32) {
  EXPECT_EQ(crc32_of("123456789"), 0xCBF43926u);
}

TEST(CheckpointFile, EveryFlippedByteIsRecognised) {
  ScratchDir dir("checkpoint_file");
  const auto path = dir / "a.ckpt";
  write_checkpoint(path.string(), sample_header(), std::string(64, 'x'));
  const std::string good = read_bytes(path);
  for (std::size_t k = 0; k < good.size(); ++k) {
    std::string bad = good;
    bad[k] = static_cast<char>(bad[k] ^ 0x10);
    write_bytes(path, bad);
    EXPECT_NE(refusal(path), "") << "byte " << k << " of " << good.size();
  }
}

TEST(CheckpointFile, EveryCutIsRecognised) {
  ScratchDir dir("checkpoint_file");
  const auto path = dir / "a.ckpt";
  write_checkpoint(path.string(), sample_header(), std::string(64, 'x'));
  const std::string good = read_bytes(path);
  for (std::size_t length = 0; length < good.size(); ++length) {
    write_bytes(path, good.substr(0, length));
    EXPECT_NE(refusal(path), "") << "cut to " << length << " bytes";
  }
  write_bytes(path, good.substr(0, good.size() - 1));
  EXPECT_NE(refusal(path).find("where the header promises"), std::string::npos) << refusal(path);
}

TEST(CheckpointFile, MessagesSayWhatIsWrong) {
  ScratchDir dir("checkpoint_file");
  const auto path = dir / "a.ckpt";
  write_checkpoint(path.string(), sample_header(), std::string(64, 'x'));
  const std::string good = read_bytes(path);

  std::string changed = good;
  changed[40] = static_cast<char>(changed[40] ^ 1);
  write_bytes(path, changed);
  EXPECT_EQ(refusal(path), path.string() + ": checksum mismatch (the file was changed or damaged)");

  std::string other_format = good;
  other_format[8] = 9;  // the format number's low byte
  write_bytes(path, other_format);
  EXPECT_EQ(refusal(path), path.string() + ": checkpoint format 9, this sluice reads format 1");

  write_bytes(path, "time,x\n0,1\n");
  EXPECT_EQ(refusal(path), path.string() + ": not a sluice checkpoint (no SLUICECP header)");

  EXPECT_NE(refusal(dir / "missing.ckpt").find("cannot open"), std::string::npos);
}

}  // namespace
}  // namespace sluice::io
