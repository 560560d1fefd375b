#include "sluice/sim/frame_output.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <span>
#include <system_error>
#include <utility>
#include <vector>

#include "sluice/core/errors.hpp"

namespace sluice {

FrameOutput::FrameOutput(const std::string& out_dir, const std::string& case_name,
                         const Communicator& ranks)
    : out_dir_(out_dir), series_path_(out_dir + "/" + case_name + ".pvd"), ranks_(ranks) {
  if (ranks.rank() == 0) series_.emplace(series_path_);
  std::error_code error;
  std::filesystem::create_directories(out_dir + "/frames", error);
  if (error) {
    throw InputError(out_dir, 0, "", "cannot create the output directory: " + error.message());
  }
}

namespace {
// `components` values an element as Float32: a plane's vector (two) as (x, 0, z).
std::vector<float> as_float(std::span<const double> values, int components) {
  std::vector<float> out;
  if (components != 2) {
    out.reserve(values.size());
    for (const double v : values) out.push_back(static_cast<float>(v));
    return out;
  }
  out.reserve(values.size() / 2 * 3);
  for (std::size_t i = 0; i < values.size(); i += 2) {
    out.push_back(static_cast<float>(values[i]));
    out.push_back(0.0f);
    out.push_back(static_cast<float>(values[i + 1]));
  }
  return out;
}

io::PointArrayF32 float_array(const FieldView& field) {
  const int components = field.components() == 2 ? 3 : field.components();
  return {field.name(), components, as_float(field.reals(), field.components())};
}
}  // namespace

io::FluidFrame frame_of(const FluidView& view) {
  io::FluidFrame frame;
  frame.points.points = as_float(view.positions.reals(), view.positions.components());
  frame.points.points_per_cell = view.points_per_cell;
  for (const FieldView& field : view.fields) {
    if (field.is_integer()) {
      const auto values = field.integers();
      frame.points.int_arrays.push_back({field.name(), {values.begin(), values.end()}});
    } else {
      frame.points.float_arrays.push_back(float_array(field));
    }
  }
  if (view.cells) {
    io::ImageFrame grid;
    grid.cells = view.cells->count;
    grid.origin = view.cells->origin;
    grid.spacing = view.cells->spacing;
    for (const FieldView& field : view.cells->fields)
      grid.cell_arrays.push_back(float_array(field));
    frame.grid = std::move(grid);
  }
  return frame;
}

void FrameOutput::write(const FluidView& view, double time) {
  const io::FluidFrame frame = frame_of(view);
  std::vector<std::string> names;
  if (ranks_.split()) {
    // Each rank writes its own particles; the first joins the pieces in a .pvtp.
    const auto piece = [&](int rank) {
      return fmt::format("frame_{:06d}_rank_{}.vtp", frame_count_, rank);
    };
    io::write_vtp(out_dir_ + "/frames/" + piece(ranks_.rank()), frame.points);
    names.push_back(fmt::format("frames/frame_{:06d}.pvtp", frame_count_));
    if (ranks_.rank() == 0) {
      std::vector<std::string> pieces;
      for (int r = 0; r < ranks_.size(); ++r) pieces.push_back(piece(r));
      io::write_pvtp(out_dir_ + "/" + names[0], frame.points, pieces);
    }
  } else {
    names.push_back(fmt::format("frames/frame_{:06d}.vtp", frame_count_));
    io::write_vtp(out_dir_ + "/" + names[0], frame.points);
    if (frame.grid) {
      names.push_back(fmt::format("frames/grid_{:06d}.vti", frame_count_));
      io::write_vti(out_dir_ + "/" + names[1], *frame.grid);
    }
  }
  if (series_) series_->add(time, names);
  ++frame_count_;
}

}  // namespace sluice
