// Particle frames as binary VTK XML PolyData (.vtp) and a ParaView .pvd collection listing them.
// Every file is written atomically (PATH.tmp, then rename), so a killed run never leaves a
// half-written file behind: readers see either the old version or the complete new one.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

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
};

// Writes `frame` as a .vtp with raw appended data (UInt64 headers), one vertex cell per point so
// ParaView renders the points, and the arrays as PointData.
// Throws std::invalid_argument if an array size does not match the number of points, and
// std::runtime_error naming the path and the system error if the file cannot be written.
void write_vtp(const std::string& path, const PolyFrame& frame);

// A ParaView .pvd collection. Each add() rewrites the whole file atomically, so it always lists
// exactly the frames written so far. Nothing is written before the first add().
class PvdSeries {
 public:
  explicit PvdSeries(std::string path);

  void add(double time, const std::string& file_relative_to_pvd);
  const std::string& path() const;

 private:
  std::string path_;
  std::vector<std::pair<double, std::string>> entries_;
};

// Writes `text` to PATH atomically (PATH.tmp, then rename). Throws std::runtime_error on failure.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace sluice::io
