#include "sluice/fluid/wcsph/wcsph_parameters.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "sluice/fluid/free_fall_speed.hpp"
#include "sluice/fluid/wcsph/wcsph_boundaries.hpp"
#include "sluice/kernels/cubic_spline.hpp"
#include "sluice/kernels/wendland_c2.hpp"

namespace sluice {

WcsphParameters read_wcsph_parameters(const io::CaseConfig& config) {
  io::MapReader model(config.source, config.model, "model", config.model_line);
  model.required<std::string>("name");
  WcsphParameters p;
  const std::string kernel =
      model.optional_choice("kernel", "wendland", "kernel", {"wendland", "cubic_spline"});
  p.kernel = kernel == "wendland" ? KernelChoice::kWendlandC2 : KernelChoice::kCubicSpline;
  p.h_over_dx = model.optional_positive("h_over_dx", p.kernel == KernelChoice::kWendlandC2
                                                         ? WendlandC2<3>::kDefaultHOverDx
                                                         : CubicSpline<3>::kDefaultHOverDx);
  if (p.h_over_dx < 0.9 || p.h_over_dx > 2.5) {
    model.fail("h_over_dx", fmt::format("must lie in [0.9, 2.5], got {}", p.h_over_dx));
  }
  p.sound_speed = model.optional_positive("sound_speed", 0);
  p.speed_factor = model.optional_positive("speed_factor", p.speed_factor);
  p.max_speed = model.optional_positive("max_speed", 0);
  p.gamma = model.optional_positive("gamma", p.gamma);
  p.artificial_viscosity =
      model.optional_non_negative("artificial_viscosity", p.artificial_viscosity);
  p.density_diffusion = model.optional_non_negative("density_diffusion", p.density_diffusion);
  p.cfl = model.optional_positive("cfl", p.cfl);
  p.force_cfl = model.optional_positive("force_cfl", p.force_cfl);
  if (p.cfl > 1) model.fail("cfl", fmt::format("must not exceed 1, got {}", p.cfl));
  const std::string slip = model.optional<std::string>("wall_slip", "no_slip");
  if (slip != "no_slip" && slip != "free_slip") {
    model.fail("wall_slip", fmt::format("expected no_slip or free_slip, got '{}'", slip));
  }
  p.no_slip = slip == "no_slip";
  p.clamp_negative_pressure =
      model.optional_choice("negative_pressure", "keep", "negative pressure", {"clamp", "keep"}) ==
      "clamp";
  p.background_pressure = model.optional_non_negative("background_pressure", 0);
  p.boundary = model.optional_choice("boundary", p.boundary, "boundary treatment",
                                     wcsph_boundaries<3, WendlandC2<3>>().names());
  const std::string device =
      model.optional_choice("device", "cpu", "device", {"cpu", "gpu", "emulated"});
  p.device = device == "gpu"        ? WcsphDevice::kGpu
             : device == "emulated" ? WcsphDevice::kEmulated
                                    : WcsphDevice::kCpu;
  std::string why;
  if (!wcsph_device_available(p.device, why)) model.fail("device", "cannot run on the GPU: " + why);
  if (p.device != WcsphDevice::kCpu && p.boundary != "adami") {
    model.fail("device", "the device runs the adami boundary treatment only");
  }
  if (p.device != WcsphDevice::kCpu && p.background_pressure > 0) {
    model.fail("device", "the device runs no transport velocity (background_pressure)");
  }
  p.time_device_stages = model.optional<bool>("time_device_stages", p.time_device_stages);
  model.finish();

  if (p.sound_speed == 0) {
    if (p.max_speed == 0) {
      p.max_speed = free_fall_speed(config);
      if (!(p.max_speed > 0)) {
        model.fail_here(
            "cannot derive the speed of sound without gravity: set model.max_speed or "
            "model.sound_speed");
      }
    }
    p.sound_speed = p.speed_factor * p.max_speed;
  }
  return p;
}

}  // namespace sluice
