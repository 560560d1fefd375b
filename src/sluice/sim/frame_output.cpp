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

void FrameOutput::write(const io::PolyFrame& frame, double time) {
  const std::string name = fmt::format("frames/frame_{:06d}.vtp", frame_count_);
  io::write_vtp(out_dir_ + "/" + name, frame);
  series_.add(time, name);
  ++frame_count_;
}

}  // namespace sluice
