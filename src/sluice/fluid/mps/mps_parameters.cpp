#include "sluice/fluid/mps/mps_parameters.hpp"

#include <fmt/format.h>

#include "sluice/fluid/free_fall_speed.hpp"

namespace sluice {

namespace {

// A number inside (low, high) or [low, high].
double within(io::MapReader& model, const std::string& key, double fallback, double low,
              double high, bool closed) {
  const double value = model.optional<double>(key, fallback);
  const bool inside = closed ? (value >= low && value <= high) : (value > low && value < high);
  if (!inside) {
    model.fail(key, fmt::format("must lie in {}{}, {}{}, got {}", closed ? "[" : "(", low, high,
                                closed ? "]" : ")", value));
  }
  return value;
}

// C_e of an effective radius: at least the first ring of neighbours, at most a reach whose
// neighbour count (some 380 in 3D) makes every operator crawl.
double effective_radius(io::MapReader& model, const std::string& key, double fallback) {
  const double value = model.optional_positive(key, fallback);
  if (value < 1.5 || value > 4.5) {
    model.fail(key, fmt::format("must lie in [1.5, 4.5], got {}", value));
  }
  return value;
}

}  // namespace

MpsParameters read_mps_parameters(const io::CaseConfig& config) {
  io::MapReader model(config.source, config.model, "model", config.model_line);
  model.required<std::string>("name");
  MpsParameters p;
  p.variant = model.optional_choice("variant", "incompressible", "variant",
                                    {"incompressible", "explicit"}) == "explicit"
                  ? MpsVariant::kExplicit
                  : MpsVariant::kIncompressible;
  p.re_over_dx = effective_radius(model, "re_over_dx", p.re_over_dx);
  p.laplacian_re_over_dx = effective_radius(model, "laplacian_re_over_dx", p.re_over_dx);
  p.surface_threshold = within(model, "surface_threshold", p.surface_threshold, 0, 1, false);
  p.surface_count_ratio = within(model, "surface_count_ratio", p.surface_count_ratio, 0, 1, false);
  p.source_relaxation = within(model, "source_relaxation", p.source_relaxation, 0, 1, true);
  p.compressibility = model.optional_non_negative("compressibility", p.compressibility);
  p.pressure_memory = model.optional_choice("compressibility_form", "rate", "compressibility form",
                                            {"rate", "ikeda"}) == "rate";
  p.keep_negative_pressure =
      model.optional_choice("negative_pressure", "clamp", "negative-pressure rule",
                            {"clamp", "keep"}) == "keep";
  p.collision_distance = within(model, "collision_distance", p.collision_distance, 0, 1, true);
  p.collision_restitution =
      within(model, "collision_restitution", p.collision_restitution, 0, 1, true);
  p.gradient_correction = model.optional<bool>("gradient_correction", p.gradient_correction);
  p.emulated_device =
      model.optional_choice("device", "cpu", "device", {"cpu", "emulated"}) == "emulated";
  p.minimum_density = within(model, "gradient_minimum_density", p.minimum_density, 0, 1, true);
  p.artificial_viscosity =
      model.optional_non_negative("artificial_viscosity", p.artificial_viscosity);
  p.cfl = model.optional_positive("cfl", p.cfl);
  if (p.cfl > 1) model.fail("cfl", fmt::format("must not exceed 1, got {}", p.cfl));
  p.sound_speed = model.optional_positive("sound_speed", 0);
  p.speed_factor = model.optional_positive("speed_factor", p.speed_factor);
  p.max_speed = model.optional_positive("max_speed", 0);
  p.wall_pressure = model.optional_choice("wall_pressure", "extrapolated", "wall-pressure rule",
                                          {"extrapolated", "solved"}) == "solved"
                        ? MpsWallPressure::kSolved
                        : MpsWallPressure::kExtrapolated;
  // The explicit variant solves nothing: its walls take the pressure of their own density.
  const bool symmetric =
      p.wall_pressure == MpsWallPressure::kSolved || p.variant == MpsVariant::kExplicit;
  p.solver = model.optional_choice("solver", symmetric ? "cg_diagonal" : "bicgstab_diagonal",
                                   "solver", sparse_solver_names());
  if (!symmetric && p.solver != "bicgstab_diagonal") {
    model.fail("solver", fmt::format("{} needs a symmetric system, and extrapolated wall "
                                     "pressures make one that is not: use bicgstab_diagonal, or "
                                     "wall_pressure: solved",
                                     p.solver));
  }
  p.solver_settings.tolerance =
      model.optional_positive("solver_tolerance", p.solver_settings.tolerance);
  if (p.solver_settings.tolerance >= 1) {
    model.fail("solver_tolerance",
               fmt::format("must be below 1, got {}", p.solver_settings.tolerance));
  }
  p.solver_settings.max_iterations = static_cast<int>(
      model.optional_positive("solver_max_iterations", p.solver_settings.max_iterations));
  model.finish();

  if (p.max_speed == 0) p.max_speed = free_fall_speed(config);
  if (!(p.max_speed > 0)) {
    model.fail_here("cannot derive a speed scale without gravity: set model.max_speed");
  }
  if (p.sound_speed == 0) p.sound_speed = p.speed_factor * p.max_speed;
  return p;
}

}  // namespace sluice
