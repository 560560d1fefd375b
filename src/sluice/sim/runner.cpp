#include "sluice/sim/runner.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "sluice/core/errors.hpp"
#include "sluice/core/progress.hpp"
#include "sluice/exec/policy.hpp"
#include "sluice/io/vtk_writer.hpp"
#include "sluice/sim/body_output.hpp"
#include "sluice/sim/divergence_guard.hpp"
#include "sluice/sim/frame_output.hpp"
#include "sluice/sim/probes.hpp"
#include "sluice/sim/simulation.hpp"

namespace sluice {

namespace {

// Next multiple of `interval` strictly after `time` (with a tolerance for rounding).
double next_multiple(double time, double interval) {
  const double k = std::floor(time / interval + 1e-9) + 1;
  return k * interval;
}

template <int D>
FluidEnergy fluid_energy(const ParticleState<D>& s) {
  const auto& ps = s.particles;
  FluidEnergy e;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (!ps.is_fluid(i)) continue;
    e.kinetic += 0.5 * ps.mass[i] * ps.velocity[i].squaredNorm();
    e.potential -= ps.mass[i] * s.gravity.dot(ps.position[i]);
  }
  return e;
}

template <int D>
RunSummary run(const io::CaseConfig& config, const RunOptions& options) {
  // Build (and so validate) everything before creating the output directory: bad input
  // must leave no directory behind.
  Simulation<D> sim(config);
  FrameOutput frames(options.out_dir, config.name);
  BodyOutput body_output(options.out_dir, sim.bodies());
  std::vector<std::int32_t> body_of_point;
  for (const BodyPoint& p : sim.bodies().points())
    body_of_point.push_back(static_cast<std::int32_t>(p.body));
  auto& s = sim.state();
  Probes<D> probes(config.probes, options.out_dir + "/probes.csv",
                   sim.has_model() ? sim.model().interaction_radius() : 2 * config.spacing);
  DivergenceGuard<D> guard;
  const double end_time = options.end_time.value_or(config.end_time);

  RunSummary summary;
  summary.particles = s.particles.size();
  summary.fluid_particles = s.fluid_count;
  summary.threads = exec::thread_count();
  summary.series_path = frames.series_path();
  summary.bodies = sim.bodies().count();
  if (!options.quiet) {
    fmt::print(stderr, "sluice: {} ({}D): {} particles ({} fluid), {} bodies, {} threads\n  {}\n",
               config.name, D, summary.particles, summary.fluid_particles, summary.bodies,
               summary.threads, sim.has_model() ? sim.model().describe() : "no fluid");
  }

  auto& timers = sim.timers();
  const std::size_t output_slot = timers.slot("output");
  const std::size_t guard_slot = timers.slot("guard");
  timers.time(output_slot, [&] {
    frames.write(s.particles, s.time, body_of_point);
    probes.record(s);
    body_output.record(s.time, sim.bodies(), fluid_energy(s));
  });
  guard.remember(s);

  ProgressReporter progress(end_time, stderr, options.live_progress);
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  double next_output = next_multiple(0, config.output_interval);
  double next_probe = probes.empty() ? end_time : next_multiple(0, config.probe_interval);
  double next_body = sim.bodies().empty() ? end_time : next_multiple(0, config.body_interval);
  while (s.time < end_time * (1 - 1e-12)) {
    const double until = std::min({next_output, next_probe, next_body, end_time});
    sim.step(until);
    std::optional<std::string> problem;
    timers.time(guard_slot, [&] {
      problem = guard.check(s, sim.bodies());
      if (!problem) guard.remember(s);
    });
    if (problem) {
      frames.write(guard.last_good(), guard.last_good_time(), body_of_point);
      if (!options.quiet) progress.finish();
      throw DivergenceError(
          *problem + fmt::format("; the last good state (t = {:.6g} s) is the last frame of {}",
                                 guard.last_good_time(), frames.series_path()));
    }
    const bool at_end = s.time >= end_time * (1 - 1e-12);
    timers.time(output_slot, [&] {
      if (!probes.empty() && (s.time >= next_probe * (1 - 1e-12) || at_end)) {
        probes.record(s);
        next_probe = next_multiple(s.time, config.probe_interval);
      }
      if (!sim.bodies().empty() && (s.time >= next_body * (1 - 1e-12) || at_end)) {
        body_output.record(s.time, sim.bodies(), fluid_energy(s));
        next_body = next_multiple(s.time, config.body_interval);
      }
      if (s.time >= next_output * (1 - 1e-12) || at_end) {
        frames.write(s.particles, s.time, body_of_point);
        next_output = next_multiple(s.time, config.output_interval);
      }
    });
    if (!options.quiet) {
      const double wall = elapsed();
      progress.update(s.time, s.step, wall > 0 ? double(summary.particles) * s.step / wall : 0);
    }
  }
  if (!options.quiet) progress.finish();

  summary.steps = s.step;
  summary.simulated_time = s.time;
  summary.wall_seconds = elapsed();
  summary.frames = frames.frames_written();
  summary.solid_substeps = sim.bodies().substeps();
  summary.most_substeps_per_step = sim.bodies().most_substeps();
  summary.stages = timers.entries();
  return summary;
}

template <int D>
CheckSummary check(const io::CaseConfig& config) {
  Simulation<D> sim(config);
  const auto& s = sim.state();
  CheckSummary out;
  out.particles = s.particles.size();
  out.fluid_particles = s.fluid_count;
  out.body_particles = sim.bodies().points().size();
  out.wall_particles = out.particles - out.fluid_particles - out.body_particles;
  out.first_time_step = sim.next_time_step();
  out.model = sim.has_model() ? sim.model().describe() : "no fluid";
  out.bodies = sim.bodies().count();
  return out;
}

}  // namespace

RunSummary run_case(const io::CaseConfig& config, const RunOptions& options) {
  RunSummary summary = config.dimension == 2 ? run<2>(config, options) : run<3>(config, options);
  if (!options.stats_path.empty())
    io::write_file_atomically(options.stats_path, stats_json(summary));
  return summary;
}

CheckSummary check_case(const io::CaseConfig& config) {
  return config.dimension == 2 ? check<2>(config) : check<3>(config);
}

std::string stats_json(const RunSummary& r) {
  std::string stages;
  for (const auto& e : r.stages) {
    if (!stages.empty()) stages += ",\n";
    stages += fmt::format("    \"{}\": {:.6f}", e.name, e.seconds);
  }
  const double fluid_rate =
      r.wall_seconds > 0 ? static_cast<double>(r.fluid_particles) * r.steps / r.wall_seconds : 0;
  return fmt::format(
      "{{\n  \"particles\": {},\n  \"fluid_particles\": {},\n  \"steps\": {},\n"
      "  \"simulated_seconds\": {:.9g},\n  \"wall_seconds\": {:.6f},\n  \"threads\": {},\n"
      "  \"particle_steps_per_second\": {:.6g},\n  \"fluid_particle_steps_per_second\": {:.6g},\n"
      "  \"wall_seconds_per_simulated_second\": {:.6g},\n  \"frames\": {},\n"
      "  \"bodies\": {},\n  \"solid_substeps\": {},\n  \"solid_substeps_per_step\": {:.6g},\n"
      "  \"most_solid_substeps_in_a_step\": {},\n"
      "  \"stage_seconds\": {{\n{}\n  }}\n}}\n",
      r.particles, r.fluid_particles, r.steps, r.simulated_time, r.wall_seconds, r.threads,
      r.particle_steps_per_second(), fluid_rate,
      r.simulated_time > 0 ? r.wall_seconds / r.simulated_time : 0, r.frames, r.bodies,
      r.solid_substeps, r.steps > 0 ? double(r.solid_substeps) / r.steps : 0,
      r.most_substeps_per_step, stages);
}

}  // namespace sluice
