#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "sluice/io/csv_writer.hpp"
#include "sluice/io/vtk_writer.hpp"
#include "support/scratch_dir.hpp"

namespace sluice::io {
namespace {

namespace fs = std::filesystem;

class IoWriterTest : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  static std::string slurp(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  }

  bool has_tmp_file() const {
    for (const auto& entry : fs::directory_iterator(dir_.path())) {
      if (entry.path().extension() == ".tmp") return true;
    }
    return false;
  }

  test_support::ScratchDir dir_{"sluice_io_test"};
};

PolyFrame sample_frame(int n) {
  PolyFrame frame;
  PointArrayF32 velocity{"velocity", 3, {}};
  PointArrayF32 pressure{"pressure", 1, {}};
  PointArrayF32 density{"density", 1, {}};
  PointArrayI32 kind{"kind", {}};
  for (int i = 0; i < n; ++i) {
    frame.points.insert(frame.points.end(), {0.1f * i, 0.2f * i, 0.3f * i});
    velocity.values.insert(velocity.values.end(), {1.0f * i, -1.0f * i, 0.5f});
    pressure.values.push_back(100.0f * i);
    density.values.push_back(1000.0f + i);
    kind.values.push_back(i % 2);
  }
  frame.float_arrays = {velocity, pressure, density};
  frame.int_arrays = {kind};
  return frame;
}

// Reads the appended block that the DataArray named NAME points to.
template <class T>
std::vector<T> read_block(const std::string& file, const std::string& name) {
  const size_t array = file.find("Name=\"" + name + "\"");
  const size_t offset_at = file.find("offset=\"", array) + std::strlen("offset=\"");
  const size_t offset = std::stoull(file.substr(offset_at));
  const size_t data = file.find("<AppendedData encoding=\"raw\">");
  const size_t block = file.find('_', data) + 1 + offset;
  uint64_t bytes = 0;
  std::memcpy(&bytes, file.data() + block, sizeof bytes);
  std::vector<T> values(bytes / sizeof(T));
  std::memcpy(values.data(), file.data() + block + sizeof bytes, bytes);
  return values;
}

TEST_F(IoWriterTest, WritesVtpAtomically) {
  const PolyFrame frame = sample_frame(5);
  write_vtp(path("frame.vtp"), frame);

  ASSERT_TRUE(fs::exists(path("frame.vtp")));
  EXPECT_FALSE(has_tmp_file());
  const std::string file = slurp(path("frame.vtp"));
  EXPECT_TRUE(file.starts_with("<?xml") || file.starts_with("<VTKFile"));
  EXPECT_NE(file.find("type=\"PolyData\""), std::string::npos);
  EXPECT_NE(file.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(file.find("NumberOfPoints=\"5\""), std::string::npos);
  EXPECT_NE(file.find("NumberOfVerts=\"5\""), std::string::npos);

  EXPECT_EQ(read_block<float>(file, "Points"), frame.points);
  EXPECT_EQ(read_block<float>(file, "velocity"), frame.float_arrays[0].values);
  EXPECT_EQ(read_block<float>(file, "density"), frame.float_arrays[2].values);
  EXPECT_EQ(read_block<int32_t>(file, "kind"), frame.int_arrays[0].values);
  EXPECT_EQ(read_block<int64_t>(file, "connectivity"), (std::vector<int64_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(read_block<int64_t>(file, "offsets"), (std::vector<int64_t>{1, 2, 3, 4, 5}));
}

TEST_F(IoWriterTest, OverwritesExistingVtp) {
  write_vtp(path("frame.vtp"), sample_frame(5));
  write_vtp(path("frame.vtp"), sample_frame(3));
  EXPECT_NE(slurp(path("frame.vtp")).find("NumberOfPoints=\"3\""), std::string::npos);
  EXPECT_FALSE(has_tmp_file());
}

TEST_F(IoWriterTest, VtpInMissingDirectoryThrows) {
  const std::string missing = path("no_such_dir/frame.vtp");
  try {
    write_vtp(missing, sample_frame(5));
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(missing), std::string::npos) << error.what();
  }
  EXPECT_FALSE(fs::exists(dir_ / "no_such_dir"));
}

TEST_F(IoWriterTest, MismatchedArraySizeThrows) {
  PolyFrame frame = sample_frame(5);
  frame.float_arrays[1].values.pop_back();
  EXPECT_THROW(write_vtp(path("frame.vtp"), frame), std::invalid_argument);
  EXPECT_FALSE(fs::exists(path("frame.vtp")));
}

TEST_F(IoWriterTest, PvtpJoinsThePiecesWithTheirArrays) {
  PolyFrame like;
  like.points = {0, 0, 0};
  like.float_arrays.push_back({"velocity", 3, {1, 2, 3}});
  like.int_arrays.push_back({"kind", {0}});
  write_pvtp(path("f.pvtp"), like, {"f_rank_0.vtp", "f_rank_1.vtp"});
  EXPECT_EQ(slurp(path("f.pvtp")),
            "<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"PPolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
            "header_type=\"UInt64\">\n"
            "  <PPolyData GhostLevel=\"0\">\n"
            "    <PPointData>\n"
            "      <PDataArray type=\"Float32\" Name=\"velocity\" NumberOfComponents=\"3\"/>\n"
            "      <PDataArray type=\"Int32\" Name=\"kind\"/>\n"
            "    </PPointData>\n"
            "    <PPoints>\n"
            "      <PDataArray type=\"Float32\" Name=\"Points\" NumberOfComponents=\"3\"/>\n"
            "    </PPoints>\n"
            "    <Piece Source=\"f_rank_0.vtp\"/>\n"
            "    <Piece Source=\"f_rank_1.vtp\"/>\n"
            "  </PPolyData>\n"
            "</VTKFile>\n");
  EXPECT_FALSE(has_tmp_file());
}

TEST_F(IoWriterTest, PvdListsEveryAddedFrame) {
  PvdSeries series(path("series.pvd"));
  EXPECT_EQ(series.path(), path("series.pvd"));
  series.add(0.0, "frame_000000.vtp");
  series.add(0.0125, "frame_000001.vtp");

  EXPECT_FALSE(has_tmp_file());
  const std::string pvd = slurp(path("series.pvd"));
  EXPECT_NE(pvd.find("type=\"Collection\""), std::string::npos);
  EXPECT_NE(pvd.find("timestep=\"0\" group=\"\" part=\"0\" file=\"frame_000000.vtp\""),
            std::string::npos);
  EXPECT_NE(pvd.find("timestep=\"0.0125\" group=\"\" part=\"0\" file=\"frame_000001.vtp\""),
            std::string::npos);
}

TEST_F(IoWriterTest, WriteFileAtomicallyReplacesContent) {
  write_file_atomically(path("stats.json"), "{\"a\": 1}\n");
  write_file_atomically(path("stats.json"), "{\"a\": 2}\n");
  EXPECT_EQ(slurp(path("stats.json")), "{\"a\": 2}\n");
  EXPECT_FALSE(has_tmp_file());
}

TEST_F(IoWriterTest, CsvRoundTrip) {
  {
    CsvWriter csv(path("probes.csv"), {"time [s]", "p1 pressure [Pa]", "note, quoted"});
    csv.row({0.0, 101325.0, 1.0});
    csv.row({0.001, 1.0 / 3.0, -2.5e-7});
    EXPECT_THROW(csv.row({1.0}), std::invalid_argument);
  }
  EXPECT_EQ(slurp(path("probes.csv")),
            "time [s],p1 pressure [Pa],\"note, quoted\"\n"
            "0,101325,1\n"
            "0.001,0.333333333,-2.5e-07\n");
}

TEST_F(IoWriterTest, CsvInMissingDirectoryThrows) {
  EXPECT_THROW(CsvWriter(path("no_such_dir/probes.csv"), {"t"}), std::runtime_error);
}

}  // namespace
}  // namespace sluice::io
