#include "sluice/sim/frame_output.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <system_error>

#include "sluice/core/errors.hpp"

namespace sluice {

FrameOutput::FrameOutput(const std::string& out_dir, const std::string& case_name)
    : out_dir_(out_dir), series_(out_dir + "/" + case_name + ".pvd") {
  std::error_code error;
  std::filesystem::create_directories(out_dir + "/frames", error);
  if (error) {
    throw InputError(out_dir, 0, "", "cannot create the output directory: " + error.message());
  }
}

void FrameOutput::write(const io::FluidFrame& frame, double time) {
  std::vector<std::string> names{fmt::format("frames/frame_{:06d}.vtp", frame_count_)};
  io::write_vtp(out_dir_ + "/" + names[0], frame.points);
  if (frame.grid) {
    names.push_back(fmt::format("frames/grid_{:06d}.vti", frame_count_));
    io::write_vti(out_dir_ + "/" + names[1], *frame.grid);
  }
  series_.add(time, names);
  ++frame_count_;
}

}  // namespace sluice
