#include "sluice/sim/case_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "sluice/core/errors.hpp"
#include "sluice/core/progress.hpp"
#include "sluice/exec/policy.hpp"
#include "sluice/sim/body_output.hpp"
#include "sluice/sim/checkpoints.hpp"
#include "sluice/sim/divergence_guard.hpp"
#include "sluice/sim/frame_output.hpp"
#include "sluice/sim/probes.hpp"
#include "sluice/sim/rigid_bodies.hpp"
#include "sluice/sim/simulation.hpp"
#include "sluice/sim/size_estimate.hpp"
#include "sluice/sim/step_collapse.hpp"

namespace sluice {

namespace {

bool reached(double time, double due) {
  return time >= due * (1 - 1e-12);
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

// "one rank", "3 ranks".
std::string ranks_named(std::size_t ranks) {
  return ranks == 1 ? "one rank" : fmt::format("{} ranks", ranks);
}

}  // namespace

std::unique_ptr<SteppedSimulation> make_simulation(const io::CaseConfig& config,
                                                   const ModelServices& services) {
  if (config.dimension == 2) return std::make_unique<Simulation<2>>(config, services);
  return std::make_unique<Simulation<3>>(config, services);
}

double next_multiple(double time, double interval) {
  const double k = std::floor(time / interval + 1e-9) + 1;
  return k * interval;
}

// The run's outputs and its bookkeeping beside the simulation.
struct CaseRun::Outputs {
  Communicator ranks;
  bool first_rank = true;
  std::string model;
  CheckpointFolder checkpoint_folder;
  io::CheckpointHeader identity;
  RunSchedule schedule;
  std::optional<FrameOutput> frames;
  std::optional<BodyOutput> body_output;  // the first rank's
  std::optional<Probes> probes;
  std::optional<DivergenceGuard> guard;
  std::optional<ProgressReporter> progress;
  // A resume on another number of ranks: how many wrote the checkpoint (0: the same number).
  std::size_t written_ranks = 0;
  long first_step = 0, first_substeps = 0;
  double start_time = 0;
  int checkpoints = 0;
  std::size_t output_slot = 0, guard_slot = 0, checkpoint_slot = 0;
  std::chrono::steady_clock::time_point start_wall;
  RunSummary sizes;  // the counts the start found

  Outputs(const std::string& out_dir, const Communicator& communicator,
          const io::CheckpointHeader& header)
      : ranks(communicator),
        first_rank(communicator.rank() == 0),
        checkpoint_folder(out_dir, communicator),
        identity(header) {}

  // A row of the bodies' files at t (the fluid's energy is a sum over the ranks: every rank
  // works it out, the first writes it).
  void record_bodies(SteppedSimulation& sim, double t) {
    const FluidEnergy energy = sim.fluid().observation().energy();
    if (body_output) body_output->record(t, sim.bodies(), sim.coupler(), energy);
  }

  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_wall).count();
  }

  // A whole run's state, the simulation first: a checkpoint that does not fit the case fails
  // there, before the output files are touched (reading back cuts them to the checkpoint).
  // On several ranks each writes its own; the files of probes and bodies are the first rank's.
  void archive_run(StateArchive& a, SteppedSimulation& sim) {
    schedule.archive_state(a);
    sim.archive_state(a);
    frames->archive_state(a);
    a.section("probes");
    probes->archive_state(a);
    if (body_output) body_output->archive_state(a);
  }

  // Resumes from `pieces`, each writing rank's checkpoint of one step, on another number of
  // ranks: the parts every rank held alike (schedule, bodies, frames' count) from any piece; the
  // fluid gathers each piece's particles and splits them anew; the first rank's files (probes,
  // bodies, the series), which only the first piece holds, are the first rank's to read. The
  // first piece is read last, so that what it holds is what stands.
  void resume_redistributed(const std::vector<io::Checkpoint>& pieces, SteppedSimulation& sim) {
    sim.fluid().begin_gathering(static_cast<int>(pieces.size()));
    for (std::size_t k = 1; k <= pieces.size(); ++k) {
      const bool first_piece = k == pieces.size();
      StateArchive archive(pieces[k % pieces.size()].state);
      if (first_piece && body_output) {
        archive_run(archive, sim);
        archive.finish();
      } else {
        schedule.archive_state(archive);
        sim.archive_state(archive);
        if (first_piece) frames->archive_state(archive);  // the count alone, off the first rank
      }
    }
    sim.fluid().end_gathering();
  }
};

CaseRun::CaseRun(const io::CaseConfig& config, const RunOptions& options)
    : dimension_(config.dimension),
      end_time_(options.end_time.value_or(config.end_time)),
      out_dir_(options.out_dir) {
  // Build (and so validate) everything before creating the output directory: bad input
  // must leave no directory behind; and nothing is allocated for a case that cannot fit.
  const SizeEstimate estimate = estimate_size(config);
  refuse_if_it_cannot_fit_here(config, estimate);
  // On several ranks every rank runs this, in step; the first writes the shared files and
  // speaks.
  const Communicator ranks = options.ranks != nullptr ? *options.ranks : Communicator();
  quiet_ = options.quiet || ranks.rank() != 0;
  sim_ = make_simulation(config, ModelServices{options.hypre, &ranks});
  SteppedSimulation& sim = *sim_;
  outputs_ = std::make_unique<Outputs>(options.out_dir, ranks,
                                       checkpoint_header(config, config.dimension));
  Outputs& o = *outputs_;
  o.model = config.has_fluid() ? config.model_name : "bodies-alone";
  std::optional<io::Checkpoint> resumed;
  // A checkpoint written on another number of ranks: every writing rank's piece (given back
  // once read).
  std::vector<io::Checkpoint> pieces;
  if (options.resume) {
    const auto warn = [&](const std::string& warning) {
      if (!options.quiet) fmt::print(stderr, "warning: {}\n", warning);  // each rank's own
    };
    pieces = pieces_written_on_another_count(o.checkpoint_folder, o.identity, warn);
    if (pieces.empty()) {
      resumed = newest_checkpoint_of_every_rank(o.checkpoint_folder, o.identity, warn, ranks);
    } else {
      resumed = pieces.front();
      o.written_ranks = pieces.size();
    }
    if (resumed->header.time >= end_time_ * (1 - 1e-12)) {
      throw InputError(o.checkpoint_folder.path(), 0, "",
                       fmt::format("the run already reached t = {:.6g} s, its end time is {:.6g} "
                                   "s: give --end a later time to go on",
                                   resumed->header.time, end_time_));
    }
  } else {
    const TimeStep first = sim.next_time_step();
    if (const auto collapsed = collapsed_step(first, first, 0, end_time_, o.model)) {
      throw DivergenceError(diverged_at(0, 0) + *collapsed);
    }
    o.schedule.first_dt = first.dt;
    o.schedule.first_limit = first.limit;
  }
  const io::CsvStart start = resumed ? io::CsvStart::kContinue : io::CsvStart::kNew;
  o.frames.emplace(options.out_dir, config.name, ranks);
  try {
    if (o.first_rank) {
      o.body_output.emplace(options.out_dir, sim.bodies(), config.travel_direction, config.gravity,
                            dimension_, start);
    }
    o.probes.emplace(config.probes, o.first_rank ? options.out_dir + "/probes.csv" : "", start);
    if (options.keep_probe_record) o.probes->keep_record();
    if (!pieces.empty()) {
      o.resume_redistributed(pieces, sim);
      pieces = {};
    } else if (resumed) {
      StateArchive archive(resumed->state);
      o.archive_run(archive, sim);
      archive.finish();
    }
  } catch (const StateArchiveError& e) {
    throw InputError(resumed->path, 0, "", fmt::format("cannot resume: {}", e.what()));
  } catch (const std::runtime_error& e) {
    if (!resumed) throw;
    throw InputError(options.out_dir, 0, "", fmt::format("cannot resume: {}", e.what()));
  }
  const FluidObservation& fluid = sim.fluid().observation();
  AxisBox escape_box = config.domain;
  escape_box.min.array() -= sim.fluid().interaction_radius();
  escape_box.max.array() += sim.fluid().interaction_radius();
  o.guard.emplace(escape_box, dimension_);

  RunSummary& sizes = o.sizes;
  const FluidSize size = fluid.size();  // over the ranks: every rank asks
  sizes.particles = size.elements;
  sizes.element_name = size.element_name;
  sizes.fluid_particles = size.fluid;
  sizes.threads = exec::thread_count();
  sizes.series_path = o.frames->series_path();
  sizes.bodies = sim.bodies().count();
  sizes.ranks = ranks.size();
  o.start_time = sim.time();
  o.first_step = sim.clock().step;
  o.first_substeps = sim.bodies().substeps();
  if (!quiet_) {
    fmt::print(stderr, "sluice: {} ({}D): {} {} ({} fluid), {} bodies, {} threads{}\n  {}\n",
               config.name, dimension_, sizes.particles, size.element_name, sizes.fluid_particles,
               sizes.bodies, sizes.threads,
               ranks.split() ? fmt::format(" on each of {} ranks", ranks.size()) : "",
               sim.fluid().describe());
    if (const std::string decomposition = sim.fluid().decomposition(); !decomposition.empty())
      fmt::print(stderr, "  {}\n", decomposition);
    if (const std::string division = sim.bodies_division(); !division.empty())
      fmt::print(stderr, "  {}\n", division);
    if (resumed) {
      fmt::print(stderr, "  resuming from {} at t = {:.6g} s (step {}) to t = {:.6g} s{}\n",
                 resumed->path, sim.time(), o.first_step, end_time_,
                 o.written_ranks == 0
                     ? ""
                     : fmt::format(", written on {}, split anew over {}",
                                   ranks_named(o.written_ranks), ranks_named(ranks.size())));
    } else {
      fmt::print(stderr,
                 "  first time step {:.3g} s, limited by {}: about {:.3g} steps to t = "
                 "{:.6g} s\n",
                 o.schedule.first_dt, o.schedule.first_limit, end_time_ / o.schedule.first_dt,
                 end_time_);
    }
  }

  auto& timers = sim.timers();
  o.output_slot = timers.slot("output");
  o.guard_slot = timers.slot("guard");
  o.checkpoint_slot = timers.slot("checkpoint");
  if (!resumed) {
    if (o.first_rank) o.checkpoint_folder.clear();
    timers.time(o.output_slot, [&] {
      o.frames->write(fluid.view(), sim.time());
      o.probes->record(sim.time(), fluid);
      o.record_bodies(sim, sim.time());
    });
    o.schedule.next_output = next_multiple(0, config.output_interval);
    o.schedule.next_probe = o.probes->empty() ? std::numeric_limits<double>::infinity()
                                              : next_multiple(0, config.probe_interval);
    o.schedule.next_body = next_multiple(0, config.body_interval);
    o.schedule.next_checkpoint =
        config.checkpoint_interval > 0 ? next_multiple(0, config.checkpoint_interval) : 0;
  }
  sim.fluid().guard().remember_good(sim.time());  // the guard's last good state
  o.progress.emplace(end_time_, stderr, options.live_progress && !quiet_, 10.0, sim.time());
  o.start_wall = std::chrono::steady_clock::now();
}

CaseRun::~CaseRun() = default;

double CaseRun::time() const {
  return sim_->time();
}
long CaseRun::step_count() const {
  return sim_->clock().step;
}
const io::CaseConfig& CaseRun::config() const {
  return sim_->config();
}
const FluidObservation& CaseRun::fluid() const {
  return sim_->fluid().observation();
}
const RigidBodies& CaseRun::bodies() const {
  return sim_->bodies();
}
const Coupler& CaseRun::coupler() const {
  return sim_->coupler();
}
void CaseRun::command_velocity(std::size_t b, const Vec3& velocity, const Vec3& angular_velocity) {
  sim_->bodies().command_velocity(b, time(), velocity, angular_velocity);
}
std::vector<std::string> CaseRun::probe_labels() const {
  return outputs_->probes->labels();
}
const std::vector<std::vector<double>>& CaseRun::probe_record() const {
  return outputs_->probes->recorded();
}
std::vector<double> CaseRun::probe_values() const {
  return outputs_->probes->measure(sim_->fluid().observation());
}

void CaseRun::step(double until) {
  SteppedSimulation& sim = *sim_;
  Outputs& o = *outputs_;
  const io::CaseConfig& config = sim.config();
  const FluidObservation& fluid = sim.fluid().observation();
  FluidGuard& fluid_guard = sim.fluid().guard();
  auto& timers = sim.timers();
  // Where the end (or `until`) and an output fall within rounding of each other, the step lands
  // on the output's time, as it does in a run that goes on past it: else a run stopped there
  // and resumed would differ from that run by its last step's rounding, and so everywhere.
  const double scheduled =
      std::min({o.schedule.next_output, o.schedule.next_probe, o.schedule.next_body});
  const double stop = std::min(end_time_, until);
  const double due = reached(stop, scheduled) ? scheduled : stop;
  const double before = sim.time();
  sim.step(due);
  const double t = sim.time();
  if (o.body_output) o.body_output->accumulate(t - before, sim.bodies(), sim.coupler());
  std::optional<std::string> problem;
  timers.time(o.guard_slot, [&] {
    problem = o.guard->check(sim.clock(), fluid_guard, sim.bodies());
    if (!problem) {
      if (const auto collapsed =
              collapsed_step(sim.last_stable_step(), o.schedule.first(), t, end_time_, o.model)) {
        problem = diverged_at(sim.clock().step, t) + *collapsed;
      }
    }
    if (!problem) fluid_guard.remember_good(t);
  });
  if (problem) {
    o.frames->write(fluid_guard.last_good_view(), fluid_guard.last_good_time());
    if (!quiet_) o.progress->finish();
    throw DivergenceError(
        *problem + fmt::format("; the last good state (t = {:.6g} s) is the last frame of {}",
                               fluid_guard.last_good_time(), o.frames->series_path()));
  }
  const bool at_end = reached(t, end_time_);
  timers.time(o.output_slot, [&] {
    if (!o.probes->empty() && (reached(t, o.schedule.next_probe) || at_end)) {
      o.probes->record(t, fluid);
      o.schedule.next_probe = next_multiple(t, config.probe_interval);
    }
    if (reached(t, o.schedule.next_body) || at_end) {
      o.record_bodies(sim, t);
      o.schedule.next_body = next_multiple(t, config.body_interval);
    }
    if (reached(t, o.schedule.next_output) || at_end) {
      o.frames->write(fluid.view(), t);
      o.schedule.next_output = next_multiple(t, config.output_interval);
    }
  });
  // After the outputs of the step, which the checkpoint counts as written. A checkpoint does
  // not shorten a step: a run with checkpoints takes the same steps as one without.
  if (config.checkpoint_interval > 0 && (reached(t, o.schedule.next_checkpoint) || at_end)) {
    o.schedule.next_checkpoint = next_multiple(t, config.checkpoint_interval);
    write_checkpoint();
  }
  if (!quiet_) {
    const double wall = o.elapsed();
    const long steps = sim.clock().step - o.first_step;
    o.progress->update(t, sim.clock().step,
                       wall > 0 ? double(o.sizes.particles) * steps / wall : 0);
    if (at_end) o.progress->finish();
  }
}

void CaseRun::write_checkpoint() {
  SteppedSimulation& sim = *sim_;
  Outputs& o = *outputs_;
  sim.timers().time(o.checkpoint_slot, [&] {
    StateArchive archive;
    o.archive_run(archive, sim);
    io::CheckpointHeader header = o.identity;
    header.time = sim.time();
    header.step = sim.clock().step;
    o.checkpoint_folder.write(header, archive.bytes());
    // Resumed on another number of ranks: once every rank holds its own checkpoint, the
    // ones it resumed from go (a later resume must not find two runs' checkpoints).
    if (o.written_ranks > 0 && o.checkpoints == 0) {
      o.ranks.barrier();
      if (o.first_rank) o.checkpoint_folder.remove_other_counts();
    }
  });
  ++o.checkpoints;
}

RunSummary CaseRun::summary() const {
  const SteppedSimulation& sim = *sim_;
  const Outputs& o = *outputs_;
  RunSummary summary = o.sizes;
  summary.start_time = o.start_time;
  summary.checkpoints = o.checkpoints;
  summary.steps = sim.clock().step - o.first_step;
  summary.last_step = sim.clock().step;
  summary.simulated_time = sim.time();
  summary.wall_seconds = o.elapsed();
  summary.frames = o.frames->frames_written();
  summary.solid_substeps = sim.bodies().substeps() - o.first_substeps;
  summary.most_substeps_per_step = sim.coupler().most_substeps();
  summary.most_exchanges_per_step = sim.coupler().most_exchanges();
  summary.body_islands = sim.body_islands();
  summary.bodies_advanced_on_first_rank = sim.bodies_advanced_here();
  summary.velocity_steps = sim.bodies().system().rigid().velocity_steps();
  summary.stages = sim_->timers().entries();
  const FluidObservation& fluid = sim.fluid().observation();
  summary.fluid_counters = fluid.counters();
  const std::vector<std::string> labels = o.probes->labels();
  const std::vector<double> values = o.probes->measure(fluid);
  for (std::size_t k = 0; k < labels.size(); ++k)
    summary.final_probes.emplace_back(labels[k], values[k]);
  return summary;
}

}  // namespace sluice
