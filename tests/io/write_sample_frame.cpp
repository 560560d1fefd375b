// Writes a two-frame, ten-point series (frame_000000.vtp, frame_000001.vtp, series.pvd) into the
// directory argv[1], for checking the VTK writer with tests/io/read_frame.py.
#include <fmt/format.h>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "sluice/io/vtk_writer.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUTPUT_DIR\n", argv[0]);
    return 2;
  }
  try {
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    sluice::io::PvdSeries series((dir / "series.pvd").string());
    constexpr int kPoints = 10;
    for (int step = 0; step < 2; ++step) {
      sluice::io::PolyFrame frame;
      sluice::io::PointArrayF32 velocity{"velocity", 3, {}};
      sluice::io::PointArrayF32 pressure{"pressure", 1, {}};
      sluice::io::PointArrayF32 density{"density", 1, {}};
      sluice::io::PointArrayI32 kind{"kind", {}};
      for (int i = 0; i < kPoints; ++i) {
        frame.points.insert(frame.points.end(), {0.1f * i, 0.05f * step, 0.0f});
        velocity.values.insert(velocity.values.end(), {0.0f, -0.5f * step, 0.0f});
        pressure.values.push_back(9.81f * 1000.0f * 0.1f * i);
        density.values.push_back(1000.0f);
        kind.values.push_back(i < 2 ? 1 : 0);
      }
      frame.float_arrays = {velocity, pressure, density};
      frame.int_arrays = {kind};
      const std::string file = fmt::format("frame_{:06d}.vtp", step);
      sluice::io::write_vtp((dir / file).string(), frame);
      series.add(0.01 * step, file);
    }
    return 0;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "write_sample_frame: %s\n", error.what());
    return 1;
  }
}
