#include "sluice/fluid/penalty_sph/penalty_sph_parameters.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "sluice/core/errors.hpp"
#include "sluice/fluid/free_fall_speed.hpp"
#include "sluice/io/body_reader.hpp"

namespace sluice {

double PenaltySphParameters::smoothing_length(double spacing, int dimension) const {
  const double pi = std::numbers::pi;
  return dimension == 2 ? spacing * std::sqrt(kernel_particles / pi)
                        : spacing * std::cbrt(3 * kernel_particles / (4 * pi));
}

PenaltySphParameters read_penalty_sph_parameters(const io::CaseConfig& config) {
  io::MapReader model(config.source, config.model, "model", config.model_line);
  model.required<std::string>("name");
  PenaltySphParameters p;
  p.kernel_particles = model.optional_positive("kernel_particles", p.kernel_particles);
  if (p.kernel_particles < 5 || p.kernel_particles > 80) {
    model.fail("kernel_particles", fmt::format("must lie in [5, 80], got {}", p.kernel_particles));
  }
  p.gas_stiffness = model.optional_positive("gas_stiffness", 0);
  p.keep_negative_pressure =
      model.optional_choice("negative_pressure", "clamp", "negative-pressure rule",
                            {"clamp", "keep"}) == "keep";
  p.speed_factor = model.optional_positive("speed_factor", p.speed_factor);
  p.max_speed = model.optional_positive("max_speed", 0);
  p.muller_pressure_force = model.optional_choice("pressure_force", "consistent", "pressure force",
                                                  {"consistent", "muller"}) == "muller";
  p.artificial_viscosity =
      model.optional_non_negative("artificial_viscosity", p.artificial_viscosity);
  p.buoyancy = model.optional_non_negative("buoyancy", p.buoyancy);
  p.surface_tension = model.optional_non_negative("surface_tension", p.surface_tension);
  p.surface_threshold = model.optional_non_negative("surface_threshold", p.surface_threshold);
  p.stiffness = model.optional_positive("Ks", 0);
  p.damping = model.optional_positive("Kd", 0);
  p.wall_friction = model.optional_non_negative("wall_friction", -1);
  p.time_step = model.optional_positive("time_step", 0);
  p.cfl = model.optional_positive("cfl", p.cfl);
  if (p.cfl > 1) model.fail("cfl", fmt::format("must not exceed 1, got {}", p.cfl));
  if (model.has("solids")) {
    for (auto& layer : model.list_of_maps("solids")) {
      SolidLayerConfig s;
      s.key = layer.path();
      s.line = layer.line();
      s.box = io::read_box(layer, config.dimension);
      s.spacing_ratio = layer.required_positive("spacing_ratio");
      s.density = layer.optional_positive("density", s.density);
      s.free = layer.optional<bool>("free", false);
      if (!s.free && layer.has("material")) {
        layer.fail("material",
                   "only read for a free layer (free: true): a fixed one does not move");
      }
      s.material = io::read_material(layer, s.material);
      layer.finish();
      p.solids.push_back(s);
    }
    // Each fluid particle marks the layers it started above in the bits of one int32.
    if (p.solids.size() > 31) model.fail("solids", "at most 31 solid layers");
  }
  p.emulated_device =
      model.optional_choice("device", "cpu", "device", {"cpu", "emulated"}) == "emulated";
  if (p.emulated_device && !p.solids.empty()) {
    model.fail("device",
               "the emulated device runs penalty-sph without solid layers (model.solids); "
               "run this case with device: cpu");
  }
  model.finish();

  if (p.max_speed == 0) p.max_speed = free_fall_speed(config);
  if (!(p.max_speed > 0)) {
    model.fail_here("cannot derive a speed scale without gravity: set model.max_speed");
  }
  if (p.gas_stiffness == 0) p.gas_stiffness = std::pow(p.speed_factor * p.max_speed, 2);
  if (p.wall_friction < 0)
    p.wall_friction = config.fluid.density * config.fluid.kinematic_viscosity;
  return p;
}

template <int D>
std::vector<Vec<D>> solid_layer_points(const SolidLayerConfig& layer,
                                       const io::CaseConfig& config) {
  AxisBox inside = layer.box;
  for (int a = 0; a < 3; ++a) {
    inside.min[a] = std::max(inside.min[a], config.domain.min[a]);
    inside.max[a] = std::min(inside.max[a], config.domain.max[a]);
  }
  std::vector<Vec<D>> points = sample_box_volume<D>(inside, layer.spacing_ratio * config.spacing);
  if (points.empty()) {
    throw InputError(config.file(), layer.line, layer.key + ".spacing_ratio",
                     fmt::format("the layer holds no solid particle inside the domain at "
                                 "L_b = {} x {} m; make the box larger than L_b",
                                 layer.spacing_ratio, config.spacing));
  }
  return points;
}

template std::vector<Vec<2>> solid_layer_points<2>(const SolidLayerConfig&, const io::CaseConfig&);
template std::vector<Vec<3>> solid_layer_points<3>(const SolidLayerConfig&, const io::CaseConfig&);

std::vector<io::BodyConfig> free_solid_grains(const io::CaseConfig& config) {
  std::vector<io::BodyConfig> grains;
  const PenaltySphParameters p = read_penalty_sph_parameters(config);
  for (std::size_t k = 0; k < p.solids.size(); ++k) {
    const SolidLayerConfig& layer = p.solids[k];
    if (!layer.free) continue;
    std::vector<Vec3> centres;
    if (config.dimension == 2) {
      for (const Vec<2>& x : solid_layer_points<2>(layer, config)) centres.push_back(to_3d<2>(x));
    } else {
      centres = solid_layer_points<3>(layer, config);
    }
    for (std::size_t n = 0; n < centres.size(); ++n) {
      io::BodyConfig b;
      b.name = fmt::format("solids{}_grain{}", k, n);
      b.shape = io::BodyShape::kSphere;
      b.radius = 0.5 * layer.spacing_ratio * config.spacing;
      b.density = layer.density;
      b.position = centres[n];
      b.material = layer.material;
      b.seen_as_one_particle = true;
      b.key = layer.key;
      b.line = b.position_line = layer.line;
      b.position_file = config.file();
      grains.push_back(std::move(b));
    }
  }
  return grains;
}

}  // namespace sluice
