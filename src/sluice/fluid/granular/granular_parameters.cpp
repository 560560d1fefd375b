#include "sluice/fluid/granular/granular_parameters.hpp"

#include <fmt/format.h>

#include "sluice/fluid/free_fall_speed.hpp"
#include "sluice/fluid/monolithic_case.hpp"

namespace sluice {

GranularParameters read_granular_parameters(const io::CaseConfig& config) {
  io::MapReader model(config.source, config.model, "model", config.model_line);
  model.required<std::string>("name");
  GranularParameters p;
  const double half = 0.5 * config.spacing;
  p.radius = model.optional_positive("radius", 0.98 * half);
  if (p.radius > half * (1 + 1e-12)) {
    model.fail("radius", fmt::format("{} m does not fit the spacing {} m: spheres on the lattice "
                                     "would overlap (at most half the spacing)",
                                     p.radius, config.spacing));
  }
  p.friction = model.optional<double>("friction", p.friction);
  if (!(p.friction >= 0)) {
    model.fail("friction", fmt::format("must be zero or more, got {}", p.friction));
  }
  p.cohesion = model.optional_non_negative("cohesion", p.cohesion);
  p.restitution = model.optional_non_negative("restitution", p.restitution);
  if (p.restitution > 1) {
    model.fail("restitution", fmt::format("must lie in [0, 1], got {}", p.restitution));
  }
  p.rolling_friction = model.optional_non_negative("rolling_friction", p.rolling_friction);
  p.jitter = model.optional_non_negative("jitter", p.jitter);
  p.size_spread = model.optional_non_negative("size_spread", p.size_spread);
  if (p.size_spread >= 1) {
    model.fail("size_spread", fmt::format("must lie in [0, 1), got {}", p.size_spread));
  }
  if (p.jitter > 1) model.fail("jitter", fmt::format("must lie in [0, 1], got {}", p.jitter));
  p.packing_seed = model.optional<int>("packing_seed", p.packing_seed);
  if (p.packing_seed < 0) {
    model.fail("packing_seed", fmt::format("must be 0 or more, got {}", p.packing_seed));
  }
  p.time_step = model.optional_positive("time_step", 0);
  p.cfl = model.optional_positive("cfl", p.cfl);
  p.envelope = model.optional_positive("envelope", p.envelope);
  // Two spheres approaching each other both move cfl r a step: the envelope must cover that.
  if (p.envelope < 2 * p.cfl) {
    model.fail("envelope",
               fmt::format("must be at least twice cfl ({}), got {}", 2 * p.cfl, p.envelope));
  }
  p.max_speed = model.optional_positive("max_speed", 0);
  p.emulated_device =
      model.optional_choice("device", "cpu", "device", {"cpu", "emulated"}) == "emulated";
  model.finish();
  if (p.max_speed == 0) p.max_speed = free_fall_speed(config);
  if (!(p.max_speed > 0) && p.time_step == 0) {
    model.fail_here("cannot derive a speed scale without gravity: set model.max_speed");
  }
  return p;
}

void prepare_granular_case(io::CaseConfig& config) {
  require_complementarity(config, "granular",
                          "its spheres and the bodies meet in one velocity-level step");
}

}  // namespace sluice
