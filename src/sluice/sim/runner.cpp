#include "sluice/sim/runner.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <limits>
#include <optional>

#include "sluice/core/errors.hpp"
#include "sluice/core/progress.hpp"
#include "sluice/exec/policy.hpp"
#include "sluice/io/vtk_writer.hpp"
#include "sluice/sim/body_output.hpp"
#include "sluice/sim/checkpoints.hpp"
#include "sluice/sim/divergence_guard.hpp"
#include "sluice/sim/frame_output.hpp"
#include "sluice/sim/probes.hpp"
#include "sluice/sim/simulation.hpp"
#include "sluice/sim/size_estimate.hpp"
#include "sluice/sim/step_collapse.hpp"

namespace sluice {

namespace {

// Next multiple of `interval` strictly after `time` (with a tolerance for rounding).
double next_multiple(double time, double interval) {
  const double k = std::floor(time / interval + 1e-9) + 1;
  return k * interval;
}

// Where a run stands between steps beside the simulation: the next times of its outputs, and
// its first step, which the collapse check measures every later one against.
struct RunSchedule {
  double next_output = 0, next_probe = 0, next_body = 0, next_checkpoint = 0;
  double first_dt = 0;
  std::string first_limit;

  TimeStep first() const { return {first_dt, first_limit.c_str()}; }
  void archive_state(StateArchive& a) {
    a.section("schedule");
    a(next_output, next_probe, next_body, next_checkpoint, first_dt, first_limit);
  }
};

// A whole run's state, the simulation first: a checkpoint that does not fit the case fails
// there, before the output files are touched (reading back cuts them to the checkpoint).
// On several ranks each writes its own; the files of probes and bodies are the first rank's
// (body_output null on the others).
template <int D>
void archive_run(StateArchive& a, RunSchedule& schedule, Simulation<D>& sim, FrameOutput& frames,
                 Probes& probes, BodyOutput* body_output) {
  schedule.archive_state(a);
  sim.archive_state(a);
  frames.archive_state(a);
  a.section("probes");
  probes.archive_state(a);
  if (body_output != nullptr) body_output->archive_state(a);
}

// "one rank", "3 ranks".
std::string ranks_named(std::size_t ranks) {
  return ranks == 1 ? "one rank" : fmt::format("{} ranks", ranks);
}

// Resumes from `pieces`, each writing rank's checkpoint of one step, on another number of ranks:
// the parts every rank held alike (schedule, bodies, frames' count) from any piece; the fluid
// gathers each piece's particles and splits them anew; the first rank's files (probes, bodies,
// the series), which only the first piece holds, are the first rank's to read. The first piece
// is read last, so that what it holds is what stands.
template <int D>
void resume_redistributed(const std::vector<io::Checkpoint>& pieces, RunSchedule& schedule,
                          Simulation<D>& sim, FrameOutput& frames, Probes& probes,
                          BodyOutput* body_output) {
  sim.fluid().begin_gathering(static_cast<int>(pieces.size()));
  for (std::size_t k = 1; k <= pieces.size(); ++k) {
    const bool first_piece = k == pieces.size();
    StateArchive archive(pieces[k % pieces.size()].state);
    if (first_piece && body_output != nullptr) {
      archive_run(archive, schedule, sim, frames, probes, body_output);
      archive.finish();
    } else {
      schedule.archive_state(archive);
      sim.archive_state(archive);
      if (first_piece) frames.archive_state(archive);  // the count alone, off the first rank
    }
  }
  sim.fluid().end_gathering();
}

template <int D>
RunSummary run(const io::CaseConfig& config, const RunOptions& options) {
  // Build (and so validate) everything before creating the output directory: bad input
  // must leave no directory behind; and nothing is allocated for a case that cannot fit.
  const SizeEstimate estimate = estimate_size(config);
  refuse_if_it_cannot_fit_here(config, estimate);
  // On several ranks every rank runs this, in step; the first writes the shared files and
  // speaks.
  const Communicator ranks = options.ranks != nullptr ? *options.ranks : Communicator();
  const bool first_rank = ranks.rank() == 0;
  const bool quiet = options.quiet || !first_rank;
  Simulation<D> sim(config, ModelServices{options.hypre, &ranks});
  const double end_time = options.end_time.value_or(config.end_time);
  const std::string model = config.has_fluid() ? config.model_name : "bodies-alone";
  const CheckpointFolder checkpoint_folder(options.out_dir, ranks);
  const io::CheckpointHeader identity = checkpoint_header(config, D);
  std::optional<io::Checkpoint> resumed;
  // A checkpoint written on another number of ranks: every writing rank's piece (given back
  // once read), and how many ranks wrote them.
  std::vector<io::Checkpoint> pieces;
  std::size_t written_ranks = 0;
  RunSchedule schedule;
  if (options.resume) {
    const auto warn = [&](const std::string& warning) {
      if (!options.quiet) fmt::print(stderr, "warning: {}\n", warning);  // each rank's own
    };
    pieces = pieces_written_on_another_count(checkpoint_folder, identity, warn);
    if (pieces.empty()) {
      resumed = newest_checkpoint_of_every_rank(checkpoint_folder, identity, warn, ranks);
    } else {
      resumed = pieces.front();
      written_ranks = pieces.size();
    }
    if (resumed->header.time >= end_time * (1 - 1e-12)) {
      throw InputError(checkpoint_folder.path(), 0, "",
                       fmt::format("the run already reached t = {:.6g} s, its end time is {:.6g} "
                                   "s: give --end a later time to go on",
                                   resumed->header.time, end_time));
    }
  } else {
    const TimeStep first = sim.next_time_step();
    if (const auto collapsed = collapsed_step(first, first, 0, end_time, model)) {
      throw DivergenceError(diverged_at(0, 0) + *collapsed);
    }
    schedule.first_dt = first.dt;
    schedule.first_limit = first.limit;
  }
  const io::CsvStart start = resumed ? io::CsvStart::kContinue : io::CsvStart::kNew;
  FrameOutput frames(options.out_dir, config.name, ranks);
  std::optional<BodyOutput> body_output;
  std::optional<Probes> probes;
  try {
    if (first_rank) {
      body_output.emplace(options.out_dir, sim.bodies(), config.travel_direction, config.gravity, D,
                          start);
    }
    probes.emplace(config.probes, first_rank ? options.out_dir + "/probes.csv" : "", start);
    if (!pieces.empty()) {
      resume_redistributed(pieces, schedule, sim, frames, *probes,
                           body_output ? &*body_output : nullptr);
      pieces = {};
    } else if (resumed) {
      StateArchive archive(resumed->state);
      archive_run(archive, schedule, sim, frames, *probes, body_output ? &*body_output : nullptr);
      archive.finish();
    }
  } catch (const StateArchiveError& e) {
    throw InputError(resumed->path, 0, "", fmt::format("cannot resume: {}", e.what()));
  } catch (const std::runtime_error& e) {
    if (!resumed) throw;
    throw InputError(options.out_dir, 0, "", fmt::format("cannot resume: {}", e.what()));
  }
  const FluidObservation& fluid = sim.fluid().observation();
  FluidGuard& fluid_guard = sim.fluid().guard();
  AxisBox escape_box = config.domain;
  escape_box.min.array() -= sim.fluid().interaction_radius();
  escape_box.max.array() += sim.fluid().interaction_radius();
  DivergenceGuard guard(escape_box, D);

  RunSummary summary;
  const FluidSize size = fluid.size();  // over the ranks: every rank asks
  summary.particles = size.elements;
  summary.element_name = size.element_name;
  summary.fluid_particles = size.fluid;
  summary.threads = exec::thread_count();
  summary.series_path = frames.series_path();
  summary.bodies = sim.bodies().count();
  summary.start_time = sim.time();
  const long first_step = sim.clock().step;
  const long first_substeps = sim.bodies().substeps();
  summary.ranks = ranks.size();
  const std::string decomposition = sim.fluid().decomposition();
  if (!quiet) {
    fmt::print(stderr, "sluice: {} ({}D): {} {} ({} fluid), {} bodies, {} threads{}\n  {}\n",
               config.name, D, summary.particles, size.element_name, summary.fluid_particles,
               summary.bodies, summary.threads,
               ranks.split() ? fmt::format(" on each of {} ranks", ranks.size()) : "",
               sim.fluid().describe());
    if (!decomposition.empty()) fmt::print(stderr, "  {}\n", decomposition);
    if (const std::string division = sim.bodies_division(); !division.empty())
      fmt::print(stderr, "  {}\n", division);
    if (resumed) {
      fmt::print(stderr, "  resuming from {} at t = {:.6g} s (step {}) to t = {:.6g} s{}\n",
                 resumed->path, sim.time(), first_step, end_time,
                 written_ranks == 0
                     ? ""
                     : fmt::format(", written on {}, split anew over {}",
                                   ranks_named(written_ranks), ranks_named(ranks.size())));
    } else {
      fmt::print(stderr,
                 "  first time step {:.3g} s, limited by {}: about {:.3g} steps to t = "
                 "{:.6g} s\n",
                 schedule.first_dt, schedule.first_limit, end_time / schedule.first_dt, end_time);
    }
  }

  auto& timers = sim.timers();
  const std::size_t output_slot = timers.slot("output");
  const std::size_t guard_slot = timers.slot("guard");
  const std::size_t checkpoint_slot = timers.slot("checkpoint");
  const bool checkpointing = config.checkpoint_interval > 0;
  // The fluid's energy is a sum over the ranks: every rank works it out, the first writes it.
  const auto record_bodies = [&](double t) {
    const FluidEnergy energy = fluid.energy();
    if (body_output) body_output->record(t, sim.bodies(), sim.coupler(), energy);
  };
  if (!resumed) {
    if (first_rank) checkpoint_folder.clear();
    timers.time(output_slot, [&] {
      frames.write(fluid.view(), sim.time());
      probes->record(sim.time(), fluid);
      record_bodies(sim.time());
    });
    schedule.next_output = next_multiple(0, config.output_interval);
    schedule.next_probe = probes->empty() ? std::numeric_limits<double>::infinity()
                                          : next_multiple(0, config.probe_interval);
    schedule.next_body = next_multiple(0, config.body_interval);
    schedule.next_checkpoint = checkpointing ? next_multiple(0, config.checkpoint_interval) : 0;
  }
  fluid_guard.remember_good(sim.time());  // the guard's last good state
  const auto write_checkpoint = [&] {
    timers.time(checkpoint_slot, [&] {
      StateArchive archive;
      archive_run(archive, schedule, sim, frames, *probes, body_output ? &*body_output : nullptr);
      io::CheckpointHeader header = identity;
      header.time = sim.time();
      header.step = sim.clock().step;
      checkpoint_folder.write(header, archive.bytes());
      // Resumed on another number of ranks: once every rank holds its own checkpoint, the
      // ones it resumed from go (a later resume must not find two runs' checkpoints).
      if (written_ranks > 0 && summary.checkpoints == 0) {
        ranks.barrier();
        if (first_rank) checkpoint_folder.remove_other_counts();
      }
    });
    ++summary.checkpoints;
  };

  ProgressReporter progress(end_time, stderr, options.live_progress && first_rank, 10.0,
                            sim.time());
  const auto start_wall = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_wall).count();
  };
  const TimeStep first = schedule.first();
  while (sim.time() < end_time * (1 - 1e-12)) {
    const double until =
        std::min({schedule.next_output, schedule.next_probe, schedule.next_body, end_time});
    const double before = sim.time();
    sim.step(until);
    const double t = sim.time();
    if (body_output) body_output->accumulate(t - before, sim.bodies(), sim.coupler());
    std::optional<std::string> problem;
    timers.time(guard_slot, [&] {
      problem = guard.check(sim.clock(), fluid_guard, sim.bodies());
      if (!problem) {
        if (const auto collapsed =
                collapsed_step(sim.last_stable_step(), first, t, end_time, model)) {
          problem = diverged_at(sim.clock().step, t) + *collapsed;
        }
      }
      if (!problem) fluid_guard.remember_good(t);
    });
    if (problem) {
      frames.write(fluid_guard.last_good_view(), fluid_guard.last_good_time());
      if (!quiet) progress.finish();
      throw DivergenceError(
          *problem + fmt::format("; the last good state (t = {:.6g} s) is the last frame of {}",
                                 fluid_guard.last_good_time(), frames.series_path()));
    }
    const bool at_end = t >= end_time * (1 - 1e-12);
    timers.time(output_slot, [&] {
      if (!probes->empty() && (t >= schedule.next_probe * (1 - 1e-12) || at_end)) {
        probes->record(t, fluid);
        schedule.next_probe = next_multiple(t, config.probe_interval);
      }
      if (t >= schedule.next_body * (1 - 1e-12) || at_end) {
        record_bodies(t);
        schedule.next_body = next_multiple(t, config.body_interval);
      }
      if (t >= schedule.next_output * (1 - 1e-12) || at_end) {
        frames.write(fluid.view(), t);
        schedule.next_output = next_multiple(t, config.output_interval);
      }
    });
    // After the outputs of the step, which the checkpoint counts as written. A checkpoint does
    // not shorten a step: a run with checkpoints takes the same steps as one without.
    if (checkpointing && (t >= schedule.next_checkpoint * (1 - 1e-12) || at_end)) {
      schedule.next_checkpoint = next_multiple(t, config.checkpoint_interval);
      write_checkpoint();
    }
    if (!quiet) {
      const double wall = elapsed();
      const long steps = sim.clock().step - first_step;
      progress.update(t, sim.clock().step, wall > 0 ? double(summary.particles) * steps / wall : 0);
    }
  }
  if (!quiet) progress.finish();

  summary.steps = sim.clock().step - first_step;
  summary.last_step = sim.clock().step;
  summary.simulated_time = sim.time();
  summary.wall_seconds = elapsed();
  summary.frames = frames.frames_written();
  summary.solid_substeps = sim.bodies().substeps() - first_substeps;
  summary.most_substeps_per_step = sim.coupler().most_substeps();
  summary.most_exchanges_per_step = sim.coupler().most_exchanges();
  summary.body_islands = sim.body_islands();
  summary.bodies_advanced_on_first_rank = sim.bodies_advanced_here();
  summary.velocity_steps = sim.bodies().system().rigid().velocity_steps();
  summary.stages = timers.entries();
  summary.fluid_counters = fluid.counters();
  const std::vector<std::string> labels = probes->labels();
  const std::vector<double> values = probes->measure(fluid);
  for (std::size_t k = 0; k < labels.size(); ++k)
    summary.final_probes.emplace_back(labels[k], values[k]);
  return summary;
}

template <int D>
CheckSummary check(const io::CaseConfig& config, HypreSession* hypre) {
  const SizeEstimate estimate = estimate_size(config);
  refuse_if_it_cannot_fit_here(config, estimate);
  ModelServices services;
  services.hypre = hypre;
  Simulation<D> sim(config, services);
  const FluidSize size = sim.fluid().observation().size();
  CheckSummary out;
  out.element_name = size.element_name;
  out.particles = size.elements;
  out.fluid_particles = size.fluid;
  out.body_particles = size.body;
  out.wall_particles = size.wall;
  const TimeStep first = sim.next_time_step();
  out.first_time_step = first.dt;
  out.first_time_step_limit = first.limit;
  out.model = sim.fluid().describe();
  out.bodies = sim.bodies().count();
  out.estimated_bytes = estimate.bytes;
  return out;
}

}  // namespace

RunSummary run_case(const io::CaseConfig& config, const RunOptions& options) {
  RunSummary summary = config.dimension == 2 ? run<2>(config, options) : run<3>(config, options);
  const bool first_rank = options.ranks == nullptr || options.ranks->rank() == 0;
  if (!options.stats_path.empty() && first_rank)
    io::write_file_atomically(options.stats_path, stats_json(summary));
  return summary;
}

CheckSummary check_case(const io::CaseConfig& config, HypreSession* hypre) {
  return config.dimension == 2 ? check<2>(config, hypre) : check<3>(config, hypre);
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
      "{{\n  \"element_name\": \"{}\",\n  \"particles\": {},\n  \"fluid_particles\": {},\n"
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
      r.element_name, r.particles, r.fluid_particles, r.steps, r.last_step, r.simulated_time,
      r.start_time, r.wall_seconds, r.threads, r.ranks, r.particle_steps_per_second(), fluid_rate,
      r.simulated_time > r.start_time ? r.wall_seconds / (r.simulated_time - r.start_time) : 0,
      r.frames, r.checkpoints, r.bodies, r.solid_substeps,
      r.steps > 0 ? double(r.solid_substeps) / r.steps : 0, r.most_substeps_per_step,
      r.most_exchanges_per_step, r.body_islands, r.bodies_advanced_on_first_rank,
      json_map(velocity_solves), json_map(r.fluid_counters), json_map(r.final_probes), stages);
}

}  // namespace sluice
