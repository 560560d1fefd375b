// A run of a case that its caller steps: the simulation with its outputs (frames, probes, the
// bodies' loads, checkpoints) on the case's schedule and the divergence guard after each step.
// The command line's `run` steps one to its end (runner.cpp); Python's Simulation steps one as
// its script likes (python/).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sluice/core/types.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/sim/runner.hpp"

namespace sluice {

class Coupler;            // coupling/coupler.hpp
class FluidObservation;   // fluid/fluid_observation.hpp
class RigidBodies;        // sim/rigid_bodies.hpp
class SteppedSimulation;  // sim/simulation.hpp

struct ModelServices;  // fluid/model_entry.hpp

// The case's simulation in its dimension (throws InputError).
std::unique_ptr<SteppedSimulation> make_simulation(const io::CaseConfig& config,
                                                   const ModelServices& services);

// The next multiple of `interval` strictly after `time` (with a tolerance for rounding): when
// an output falls due.
double next_multiple(double time, double interval);

class CaseRun {
 public:
  // Builds the simulation (throws InputError; bad input leaves no directory behind), opens the
  // output in options.out_dir or, with options.resume, goes on from its newest checkpoint, and
  // writes the first frame. Unless options.quiet, says what it runs on stderr.
  CaseRun(const io::CaseConfig& config, const RunOptions& options);
  ~CaseRun();
  CaseRun(const CaseRun&) = delete;
  CaseRun& operator=(const CaseRun&) = delete;

  double time() const;
  long step_count() const;  // from the case's start
  double end_time() const { return end_time_; }
  bool finished() const { return time() >= end_time_ * (1 - 1e-12); }

  // One step, clipped so as to land on the next output's time and not to pass `until` (nor the
  // end), then the outputs that fall due and a checkpoint where one does. Throws
  // DivergenceError, after writing the last good frame, when the step went wrong; the run is
  // then of no further use.
  void step(double until);
  // A checkpoint now, as the case's checkpoint_interval would write one.
  void write_checkpoint();
  // What the run did so far, as the command line's summary and --stats report it.
  RunSummary summary() const;
  const std::string& out_dir() const { return out_dir_; }

  const io::CaseConfig& config() const;  // with the bodies the model added
  int dimension() const { return dimension_; }
  const FluidObservation& fluid() const;
  const RigidBodies& bodies() const;
  const Coupler& coupler() const;
  // From now on, prescribed body b moves on at `velocity` turning at `angular_velocity`
  // (RigidBodies::command_velocity; std::invalid_argument for another body).
  void command_velocity(std::size_t b, const Vec3& velocity, const Vec3& angular_velocity);
  // Each probe's column label ("front [m]") and its value now.
  std::vector<std::string> probe_labels() const;
  std::vector<double> probe_values() const;
  // The probes' rows recorded by this run so far (a resumed run's since its checkpoint), as
  // probes.csv holds them: the time, then each probe's value; none without
  // RunOptions::keep_probe_record.
  const std::vector<std::vector<double>>& probe_record() const;

 private:
  struct Outputs;  // case_run.cpp

  int dimension_ = 2;
  double end_time_ = 0;
  std::string out_dir_;
  bool quiet_ = false;
  std::unique_ptr<SteppedSimulation> sim_;
  std::unique_ptr<Outputs> outputs_;
};

}  // namespace sluice
