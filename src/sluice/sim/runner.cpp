#include "sluice/sim/runner.hpp"

#include <fmt/format.h>

#include "sluice/core/build_info.hpp"
#include "sluice/io/vtk_writer.hpp"
#include "sluice/sim/case_run.hpp"
#include "sluice/sim/simulation.hpp"
#include "sluice/sim/size_estimate.hpp"

namespace sluice {

RunSummary run_case(const io::CaseConfig& config, const RunOptions& options) {
  CaseRun run(config, options);
  while (!run.finished()) run.step(run.end_time());
  const RunSummary summary = run.summary();
  const bool first_rank = options.ranks == nullptr || options.ranks->rank() == 0;
  if (!options.stats_path.empty() && first_rank)
    io::write_file_atomically(options.stats_path, stats_json(summary));
  return summary;
}

CheckSummary check_case(const io::CaseConfig& config, HypreSession* hypre) {
  const SizeEstimate estimate = estimate_size(config);
  refuse_if_it_cannot_fit_here(config, estimate);
  ModelServices services;
  services.hypre = hypre;
  const std::unique_ptr<SteppedSimulation> sim = make_simulation(config, services);
  const FluidSize size = sim->fluid().observation().size();
  CheckSummary out;
  out.element_name = size.element_name;
  out.particles = size.elements;
  out.fluid_particles = size.fluid;
  out.body_particles = size.body;
  out.wall_particles = size.wall;
  const TimeStep first = sim->next_time_step();
  out.first_time_step = first.dt;
  out.first_time_step_limit = first.limit;
  out.model = sim->fluid().describe();
  out.bodies = sim->bodies().count();
  out.estimated_bytes = estimate.bytes;
  return out;
}

std::string stats_json(const RunSummary& r) {
  std::string stages;
  for (const auto& e : r.stages) {
    if (!stages.empty()) stages += ",\n";
    stages += fmt::format("    \"{}\": {:.6f}", e.name, e.seconds);
  }
  const auto json_map = [](const std::vector<std::pair<std::string, double>>& entries) {
    std::string text;
    for (const auto& [name, value] : entries)
      text += fmt::format("{}\"{}\": {:.9g}", text.empty() ? "" : ", ", name, value);
    return text;
  };
  // The velocity-level solves: how many, their iterations and their residuals [m/s].
  const VelocityStepTotals& v = r.velocity_steps;
  std::vector<std::pair<std::string, double>> velocity_solves;
  if (v.solves > 0) {
    velocity_solves = {{"solves", double(v.solves)},
                       {"iterations_per_solve", double(v.iterations) / double(v.solves)},
                       {"most_iterations", double(v.most_iterations)},
                       {"mean_residual", v.residual_sum / double(v.solves)},
                       {"largest_residual", v.largest_residual}};
  }
  const double fluid_rate =
      r.wall_seconds > 0 ? static_cast<double>(r.fluid_particles) * r.steps / r.wall_seconds : 0;
  return fmt::format(
      "{{\n  \"sluice_version\": \"{}\",\n  \"source_revision\": \"{}\",\n"
      "  \"element_name\": \"{}\",\n  \"particles\": {},\n  \"fluid_particles\": {},\n"
      "  \"steps\": {},\n  \"last_step\": {},\n"
      "  \"simulated_seconds\": {:.9g},\n  \"start_seconds\": {:.9g},\n"
      "  \"wall_seconds\": {:.6f},\n  \"threads\": {},\n  \"ranks\": {},\n"
      "  \"particle_steps_per_second\": {:.6g},\n  \"fluid_particle_steps_per_second\": {:.6g},\n"
      "  \"wall_seconds_per_simulated_second\": {:.6g},\n  \"frames\": {},\n"
      "  \"checkpoints\": {},\n"
      "  \"bodies\": {},\n  \"solid_substeps\": {},\n  \"solid_substeps_per_step\": {:.6g},\n"
      "  \"most_solid_substeps_in_a_step\": {},\n  \"most_body_exchanges_in_a_step\": {},\n"
      "  \"body_islands\": {},\n  \"bodies_advanced_on_first_rank\": {},\n"
      "  \"velocity_solves\": {{{}}},\n"
      "  \"fluid_counters\": {{{}}},\n  \"final_probes\": {{{}}},\n"
      "  \"stage_seconds\": {{\n{}\n  }}\n}}\n",
      sluice_version(), source_revision(), r.element_name, r.particles, r.fluid_particles, r.steps,
      r.last_step, r.simulated_time, r.start_time, r.wall_seconds, r.threads, r.ranks,
      r.particle_steps_per_second(), fluid_rate,
      r.simulated_time > r.start_time ? r.wall_seconds / (r.simulated_time - r.start_time) : 0,
      r.frames, r.checkpoints, r.bodies, r.solid_substeps,
      r.steps > 0 ? double(r.solid_substeps) / r.steps : 0, r.most_substeps_per_step,
      r.most_exchanges_per_step, r.body_islands, r.bodies_advanced_on_first_rank,
      json_map(velocity_solves), json_map(r.fluid_counters), json_map(r.final_probes), stages);
}

}  // namespace sluice
