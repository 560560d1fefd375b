// Frames as binary VTK XML files: points and surfaces as PolyData (.vtp), a grid's cells as
// ImageData (.vti), and a ParaView .pvd collection listing them.
// Every file is written atomically (PATH.tmp, then rename), so a killed run never leaves a
// half-written file behind: readers see either the old version or the complete new one.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sluice/core/state_archive.hpp"

namespace sluice::io {

struct PointArrayF32 {
  std::string name;
  int components = 1;
  std::vector<float> values;  // size n * components, tuple-interleaved
};

struct PointArrayI32 {
  std::string name;
  std::vector<int32_t> values;  // size n
};

struct PolyFrame {
  std::vector<float> points;  // x,y,z interleaved, size 3n
  std::vector<PointArrayF32> float_arrays;
  std::vector<PointArrayI32> int_arrays;
  // The cells: each point a vertex (1), or consecutive pairs of points line segments (2), or
  // consecutive triples triangles (3).
  int points_per_cell = 1;
};

// A grid of cells: `cells` along x, y, z (a 2D grid in the x-z plane: 1 along y), the first
// cell's lower corner at `origin`, cubes of edge `spacing`; arrays per cell, x fastest.
struct ImageFrame {
  std::array<int, 3> cells{1, 1, 1};
  std::array<double, 3> origin{0, 0, 0};
  double spacing = 1;
  std::vector<PointArrayF32> cell_arrays;
};

// What a fluid shows at one time: its particles (a grid model: its free surface), and, for a
// grid model, the grid.
struct FluidFrame {
  PolyFrame points;
  std::optional<ImageFrame> grid;
};

// Writes `frame` as a .vtp with raw appended data (UInt64 headers), its cells (vertices, lines
// or triangles) so that ParaView renders them, and the arrays as PointData.
// Throws std::invalid_argument if an array size does not match the number of points, and
// std::runtime_error naming the path and the system error if the file cannot be written.
void write_vtp(const std::string& path, const PolyFrame& frame);

// Writes a .pvtp (ParaView's parallel PolyData) that joins the .vtp `pieces` (paths relative to
// it), each written by write_vtp with the arrays of `like` (their values are not read).
// Throws std::runtime_error as write_vtp does.
void write_pvtp(const std::string& path, const PolyFrame& like,
                const std::vector<std::string>& pieces);

// Writes `frame` as a .vti (ImageData) with raw appended data and the arrays as CellData.
// Throws as write_vtp does.
void write_vti(const std::string& path, const ImageFrame& frame);

// A ParaView .pvd collection. Each add() rewrites the whole file atomically, so it always lists
// exactly the frames written so far. Nothing is written before the first add().
class PvdSeries {
 public:
  explicit PvdSeries(std::string path);

  void add(double time, const std::string& file_relative_to_pvd) {
    add(time, std::vector<std::string>{file_relative_to_pvd});
  }
  // Several files for one time, as the parts 0, 1, ... of the data set.
  void add(double time, const std::vector<std::string>& files_relative_to_pvd);
  const std::string& path() const;
  // Checkpoints: the entries; read back, the file is written anew with them.
  void archive_state(StateArchive& a);

 private:
  void write() const;

  std::string path_;
  std::vector<std::pair<double, std::vector<std::string>>> entries_;
};

// Writes `text` to PATH atomically (PATH.tmp, then rename). Throws std::runtime_error on failure.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace sluice::io
