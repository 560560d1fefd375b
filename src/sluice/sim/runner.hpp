// Running a case from start to end: steps, frames, probes, progress, summary and statistics.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sluice/core/stage_timer.hpp"
#include "sluice/io/case_config.hpp"

namespace sluice {

class HypreSession;  // linear/hypre_session.hpp
class Communicator;  // parallel/communicator.hpp

struct RunOptions {
  std::string out_dir;             // created if missing
  std::optional<double> end_time;  // overrides the case's end_time
  std::string stats_path;          // JSON statistics, if not empty
  bool live_progress = false;      // redraw one progress line (terminal)
  bool quiet = false;              // no progress and no summary
  // Continue the run in out_dir from its newest valid checkpoint (docs/output.md#checkpoints).
  bool resume = false;
  // The process's MPI and hypre, for a model whose pressure solver is hypre's; without it
  // that solver cannot solve.
  HypreSession* hypre = nullptr;
  // The run's ranks (mpirun -np N); null: this process alone. Every rank calls run_case.
  const Communicator* ranks = nullptr;
  // Keep the probes' rows in memory (CaseRun::probe_record), for a caller that steps the run.
  bool keep_probe_record = false;
};

struct RunSummary {
  std::string element_name = "particles";  // what `particles` counts: particles or cells
  std::size_t particles = 0;
  std::size_t fluid_particles = 0;
  long steps = 0;      // taken by this run (a resumed run: since its checkpoint)
  long last_step = 0;  // the step count at the end, from the case's start (a resumed run too)
  double simulated_time = 0;
  double start_time = 0;  // a resumed run: its checkpoint's time
  int checkpoints = 0;    // written by this run
  double wall_seconds = 0;
  int frames = 0;
  int threads = 1;  // on each rank
  int ranks = 1;
  std::vector<StageTimers::Entry> stages;
  std::string series_path;
  std::size_t bodies = 0;
  long solid_substeps = 0;  // solid sub-steps of this run (bodies sub-cycle within a step)
  int most_substeps_per_step = 0;
  int most_exchanges_per_step = 1;  // of the fluid's loads with the bodies (Coupler::exchanges)
  // Several ranks with ranks.bodies: islands: the islands of bodies at the last step, and how
  // many bodies the first rank advanced in it (0 and 0 otherwise).
  int body_islands = 0, bodies_advanced_on_first_rank = 0;
  VelocityStepTotals velocity_steps;  // the velocity-level solves (joints, complementarity)
  std::vector<std::pair<std::string, double>> fluid_counters;  // FluidObservation::counters()
  std::vector<std::pair<std::string, double>> final_probes;    // each probe at the end

  // This run's own steps per wall second, times the particles.
  double particle_steps_per_second() const {
    return wall_seconds > 0 ? static_cast<double>(particles) * steps / wall_seconds : 0;
  }
};

// Runs the case, or with options.resume continues it from its newest checkpoint. Throws
// InputError for bad input (or a checkpoint of another case) and DivergenceError (after
// writing the last good frame) when the run diverges.
RunSummary run_case(const io::CaseConfig& config, const RunOptions& options);

struct CheckSummary {
  std::string element_name = "particles";  // what `particles` counts: particles or cells
  std::size_t particles = 0;
  std::size_t fluid_particles = 0;
  std::size_t wall_particles = 0;
  std::size_t body_particles = 0;
  double first_time_step = 0;
  std::string first_time_step_limit;
  std::string model;
  std::size_t bodies = 0;
  double estimated_bytes = 0;  // from the geometry, before building (size_estimate.hpp)
};

// Builds the case's particles and model without running a step; first refuses (InputError at
// `spacing`) a case whose estimated memory exceeds the machine's. `hypre`: the process's session,
// for a model that solves as it is built (mac's pressure at rest) with hypre's solver.
CheckSummary check_case(const io::CaseConfig& config, HypreSession* hypre = nullptr);

// The statistics JSON written by --stats.
std::string stats_json(const RunSummary& summary);

}  // namespace sluice
