#include <fmt/format.h>

#include "sluice/fluid/fluid_model.hpp"
#include "sluice/fluid/wcsph/wcsph_model.hpp"
#include "sluice/kernels/cubic_spline.hpp"
#include "sluice/kernels/wendland_c2.hpp"

namespace sluice {

namespace {

template <int D>
std::unique_ptr<FluidModel<D>> make_wcsph(const io::CaseConfig& config) {
  const WcsphParameters p = read_wcsph_parameters(config);
  switch (p.kernel) {
    case KernelChoice::kCubicSpline:
      return std::make_unique<WcsphModel<D, CubicSpline<D>>>(p, config);
    case KernelChoice::kWendlandC2:
      break;
  }
  return std::make_unique<WcsphModel<D, WendlandC2<D>>>(p, config);
}

}  // namespace

template <int D>
std::unique_ptr<FluidModel<D>> make_fluid_model(const io::CaseConfig& config) {
  if (config.model_name == "wcsph") return make_wcsph<D>(config);
  io::MapReader model(config.source, config.model, "model", config.model_line);
  std::string problem = fmt::format("unknown model '{}'; available: wcsph", config.model_name);
  const std::string guess = io::closest_match(config.model_name, {"wcsph"});
  if (!guess.empty()) problem += fmt::format(" (did you mean '{}'?)", guess);
  model.fail("name", problem);
}

template std::unique_ptr<FluidModel<2>> make_fluid_model<2>(const io::CaseConfig&);
template std::unique_ptr<FluidModel<3>> make_fluid_model<3>(const io::CaseConfig&);

}  // namespace sluice
