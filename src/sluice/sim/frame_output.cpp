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

template <int D>
void FrameOutput::write(const ParticleSet<D>& ps, double time,
                        const std::vector<std::int32_t>& body_of_point) {
  const std::size_t n = ps.size();
  io::PolyFrame frame;
  frame.points.resize(3 * n);
  io::PointArrayF32 velocity{"velocity", 3, std::vector<float>(3 * n)};
  io::PointArrayF32 pressure{"pressure", 1, std::vector<float>(n)};
  io::PointArrayF32 density{"density", 1, std::vector<float>(n)};
  io::PointArrayI32 kind{"kind", std::vector<std::int32_t>(n)};
  io::PointArrayI32 body{"body", std::vector<std::int32_t>(n)};
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 x = to_3d<D>(ps.position[i]);
    const Vec3 v = to_3d<D>(ps.velocity[i]);
    for (int a = 0; a < 3; ++a) {
      frame.points[3 * i + a] = static_cast<float>(x[a]);
      velocity.values[3 * i + a] = static_cast<float>(v[a]);
    }
    pressure.values[i] = static_cast<float>(ps.pressure[i]);
    density.values[i] = static_cast<float>(ps.density[i]);
    kind.values[i] = static_cast<std::int32_t>(ps.kind[i]);
    if (!body_of_point.empty()) {
      body.values[i] = ps.body_point[i] < 0 ? -1 : body_of_point[ps.body_point[i]];
    }
  }
  frame.float_arrays = {std::move(velocity), std::move(pressure), std::move(density)};
  frame.int_arrays = {std::move(kind)};
  if (!body_of_point.empty()) frame.int_arrays.push_back(std::move(body));
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
