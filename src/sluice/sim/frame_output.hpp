// Writes the particles as a VTK frame (OUT/frames/frame_NNNNNN.vtp) and lists it in the
// ParaView series OUT/CASE.pvd. Arrays: the fields marked for output (velocity, pressure,
// density, kind and any a model adds; docs/output.md), and `body` in a case with bodies.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sluice/io/vtk_writer.hpp"
#include "sluice/particles/particle_set.hpp"

namespace sluice {

class FrameOutput {
 public:
  // Creates OUT/frames (throws InputError naming the directory if it cannot be created).
  FrameOutput(const std::string& out_dir, const std::string& case_name);

  // `body_of_point`: the body of each body point (RigidBodies::points()); when not empty, the
  // frame gets a `body` array (the body's index, -1 for fluid and walls).
  template <int D>
  void write(const ParticleSet<D>& particles, double time,
             const std::vector<std::int32_t>& body_of_point = {});

  // Whether a frame needs this field: those marked for output, the positions and the body
  // points (for the `body` array).
  static bool shows(const FieldLabel& label);

  int frames_written() const { return frame_count_; }
  const std::string& series_path() const { return series_.path(); }

 private:
  std::string out_dir_;
  io::PvdSeries series_;
  int frame_count_ = 0;
};

}  // namespace sluice
