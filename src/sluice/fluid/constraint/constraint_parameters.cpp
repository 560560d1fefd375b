#include "sluice/fluid/constraint/constraint_parameters.hpp"

#include <fmt/format.h>

#include "sluice/fluid/free_fall_speed.hpp"
#include "sluice/fluid/monolithic_case.hpp"

namespace sluice {

ConstraintParameters read_constraint_parameters(const io::CaseConfig& config) {
  io::MapReader model(config.source, config.model, "model", config.model_line);
  model.required<std::string>("name");
  ConstraintParameters p;
  p.h_over_dx = model.optional_positive("h_over_dx", p.h_over_dx);
  if (p.h_over_dx < 1 || p.h_over_dx > 2.5) {
    model.fail("h_over_dx", fmt::format("must lie in [1, 2.5], got {}", p.h_over_dx));
  }
  p.compliance = model.optional_positive("compliance", p.compliance);
  p.relaxation = model.optional_positive("relaxation", p.relaxation);
  p.unilateral = model.optional_choice("density_constraint", "unilateral", "density constraint",
                                       {"unilateral", "bilateral"}) == "unilateral";
  p.viscosity = model.optional_non_negative("viscosity", p.viscosity);
  p.time_step = model.optional_positive("time_step", 0);
  p.cfl = model.optional_positive("cfl", p.cfl);
  if (p.cfl > 1) model.fail("cfl", fmt::format("must not exceed 1, got {}", p.cfl));
  p.max_speed = model.optional_positive("max_speed", 0);
  p.max_iterations = static_cast<int>(model.optional_positive("max_iterations", p.max_iterations));
  p.tolerance = model.optional_positive("tolerance", p.tolerance);
  p.emulated_device =
      model.optional_choice("device", "cpu", "device", {"cpu", "emulated"}) == "emulated";
  model.finish();
  if (p.max_speed == 0) p.max_speed = free_fall_speed(config);
  if (!(p.max_speed > 0) && p.time_step == 0) {
    model.fail_here("cannot derive a speed scale without gravity: set model.max_speed");
  }
  return p;
}

void prepare_constraint_case(io::CaseConfig& config) {
  require_complementarity(config, "constraint",
                          "its density constraints and the bodies' contacts are one problem");
  const ConstraintParameters p = read_constraint_parameters(config);
  config.contact.velocity_step.solver.max_iterations = p.max_iterations;
  config.contact.velocity_step.solver.tolerance = p.tolerance;
}

}  // namespace sluice
