// Writes the fluid's frames (OUT/frames/frame_NNNNNN.vtp; a grid model's grid beside it as
// grid_NNNNNN.vti) from its view (fluid/fluid_view.hpp) and lists them in the ParaView series
// OUT/CASE.pvd (docs/output.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sluice/fluid/fluid_view.hpp"
#include "sluice/io/vtk_writer.hpp"
#include "sluice/parallel/communicator.hpp"

namespace sluice {

// The view as VTK's points and cells: reals as Float32, a plane's vectors as (x, 0, z).
io::FluidFrame frame_of(const FluidView& view);

class FrameOutput {
 public:
  // Creates OUT/frames (throws InputError naming the directory if it cannot be created). On
  // several ranks, a frame is each rank's piece (frame_NNNNNN_rank_R.vtp) and the first rank's
  // frame_NNNNNN.pvtp that joins them, which the series lists.
  FrameOutput(const std::string& out_dir, const std::string& case_name,
              const Communicator& ranks = {});

  // Writes the next frame, for `time`.
  void write(const FluidView& view, double time);

  int frames_written() const { return frame_count_; }
  const std::string& series_path() const { return series_path_; }
  // Checkpoints: the frames so far; read back, the series lists them alone (a later frame a
  // killed run wrote is written again).
  void archive_state(StateArchive& a) {
    a.section("frames");
    a(frame_count_);
    if (series_) series_->archive_state(a);
  }

 private:
  std::string out_dir_;
  std::string series_path_;
  std::optional<io::PvdSeries> series_;  // the first rank's
  int frame_count_ = 0;
  Communicator ranks_;
};

}  // namespace sluice
