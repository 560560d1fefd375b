#include "sluice/sim/frame_output.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <system_error>
#include <type_traits>

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

bool FrameOutput::shows(const FieldLabel& label) {
  return label.output || label.name == "position" || label.name == "body_point";
}

template <int D>
void FrameOutput::write(const ParticleSet<D>& ps, double time,
                        const std::vector<std::int32_t>& body_of_point) {
  const std::size_t n = ps.size();
  io::PolyFrame frame;
  frame.points.resize(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 x = to_3d<D>(ps.position[i]);
    for (int a = 0; a < 3; ++a) frame.points[3 * i + a] = static_cast<float>(x[a]);
  }
  // Every field marked for output, as Float32 (vectors in 3D) or Int32.
  ps.for_each_field([&](const FieldLabel& label, const auto& values) {
    if (!label.output) return;
    using T = typename std::decay_t<decltype(values)>::value_type;
    if constexpr (std::is_same_v<T, Vec<D>>) {
      io::PointArrayF32 array{label.name, 3, std::vector<float>(3 * n)};
      for (std::size_t i = 0; i < n; ++i) {
        const Vec3 v = to_3d<D>(values[i]);
        for (int a = 0; a < 3; ++a) array.values[3 * i + a] = static_cast<float>(v[a]);
      }
      frame.float_arrays.push_back(std::move(array));
    } else if constexpr (std::is_floating_point_v<T>) {
      io::PointArrayF32 array{label.name, 1, std::vector<float>(n)};
      for (std::size_t i = 0; i < n; ++i) array.values[i] = static_cast<float>(values[i]);
      frame.float_arrays.push_back(std::move(array));
    } else {
      io::PointArrayI32 array{label.name, std::vector<std::int32_t>(n)};
      for (std::size_t i = 0; i < n; ++i) array.values[i] = static_cast<std::int32_t>(values[i]);
      frame.int_arrays.push_back(std::move(array));
    }
  });
  if (!body_of_point.empty()) {
    io::PointArrayI32 body{"body", std::vector<std::int32_t>(n)};
    for (std::size_t i = 0; i < n; ++i) {
      body.values[i] = ps.body_point[i] < 0 ? -1 : body_of_point[ps.body_point[i]];
    }
    frame.int_arrays.push_back(std::move(body));
  }
  const std::string name = fmt::format("frames/frame_{:06d}.vtp", frame_count_);
  io::write_vtp(out_dir_ + "/" + name, frame);
  series_.add(time, name);
  ++frame_count_;
}

template void FrameOutput::write<2>(const ParticleSet<2>&, double,
                                    const std::vector<std::int32_t>&);
template void FrameOutput::write<3>(const ParticleSet<3>&, double,
                                    const std::vector<std::int32_t>&);

}  // namespace sluice
