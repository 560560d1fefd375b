// The `sluice` command line: run a case, check it, sweep its parameters, or compare models. Exit
// codes: 0 done, 1 internal failure, 2 bad input, 3 the run (or a run of a sweep) diverged.
#include <fmt/format.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "option_checks.hpp"
#include "sluice/core/build_info.hpp"
#include "sluice/core/errors.hpp"
#include "sluice/exec/policy.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/linear/hypre_session.hpp"
#include "sluice/parallel/communicator.hpp"
#include "sluice/sim/device_choice.hpp"
#include "sluice/sim/runner.hpp"
#include "sluice/sim/size_estimate.hpp"
#include "sluice/study/child_runs.hpp"
#include "sluice/study/compare.hpp"
#include "sluice/study/sweep.hpp"

namespace {

void print_summary(const sluice::RunSummary& r) {
  const std::string span =
      r.start_time > 0 ? fmt::format("t = {:.6g} to {:.6g} s", r.start_time, r.simulated_time)
                       : fmt::format("{:.6g} s", r.simulated_time);
  fmt::print(
      "done: {} simulated in {} steps, {:.2f} s wall, {:.3g} M particle-steps/s "
      "({} particles, {} threads{}), {} frames in {}\n",
      span, r.steps, r.wall_seconds, r.particle_steps_per_second() / 1e6, r.particles, r.threads,
      r.ranks > 1 ? fmt::format(" on each of {} ranks", r.ranks) : "", r.frames, r.series_path);
  if (r.checkpoints > 0) fmt::print("  checkpoints written: {}\n", r.checkpoints);
  if (r.bodies > 0) {
    fmt::print("  {} bodies: {} solid sub-steps ({:.3g} per step, at most {} in a step)\n",
               r.bodies, r.solid_substeps, r.steps > 0 ? double(r.solid_substeps) / r.steps : 0,
               r.most_substeps_per_step);
  }
  if (const auto& v = r.velocity_steps; v.solves > 0) {
    fmt::print(
        "  velocity-level solves: {}, {:.3g} iterations each (at most {}), residual {:.3g} m/s "
        "on average, at most {:.3g}\n",
        v.solves, double(v.iterations) / double(v.solves), v.most_iterations,
        v.residual_sum / double(v.solves), v.largest_residual);
  }
  for (const auto& [name, value] : r.fluid_counters) fmt::print("  {}: {:.6g}\n", name, value);
  double total = 0;
  for (const auto& e : r.stages) total += e.seconds;
  for (const auto& e : r.stages) {
    fmt::print("  {:<12} {:9.3f} s {:5.1f} %\n", e.name, e.seconds,
               total > 0 ? 100 * e.seconds / total : 0);
  }
}

// Says what went wrong and gives the exit code. On several ranks a bad case or a divergence is
// found by every rank alike: the first says it and stops them all with the code; another rank
// waits for that, and speaks and stops them itself only where the failure was its own.
int fail(const sluice::Communicator& ranks, int code, const char* what) {
  if (!ranks.split()) {
    fmt::print(stderr, "error: {}\n", what);
    return code;
  }
  if (ranks.rank() != 0) std::this_thread::sleep_for(std::chrono::seconds(10));
  fmt::print(stderr, "error: {}{}\n",
             ranks.rank() == 0 ? "" : fmt::format("rank {}: ", ranks.rank()), what);
  std::fflush(stderr);
  ranks.abort(code);
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  // Under mpirun, MPI from the start (every rank runs the same command, in step); otherwise
  // this process alone, and MPI only for hypre's solver, started by its first solve. Both stop
  // when main returns, hypre first.
  sluice::MpiSession mpi;
  const sluice::Communicator ranks = sluice::Communicator::world();
  sluice::HypreSession hypre;
  CLI::App app{"sluice: free-surface flow with rigid bodies (particle methods)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", fmt::format("sluice {} (source {})", sluice::sluice_version(),
                                                sluice::source_revision()));
  std::string case_path, out_dir, stats_path, resume_dir, device;
  std::vector<std::string> overrides;
  int threads = 0;
  double end_time = 0;

  CLI::App* run = app.add_subcommand("run", "run a case");
  run->add_option("CASE", case_path, "case file (YAML)")->required();
  CLI::Option* out_option =
      run->add_option("--out", out_dir, "output directory (default: out/CASE_NAME)");
  run->add_option("--resume", resume_dir,
                  "continue the run in this output directory from its newest checkpoint")
      ->excludes(out_option);
  run->add_option("--threads", threads, "number of threads (default: all cores)")
      ->check(sluice::at_least_one());
  run->add_option("--end", end_time, "end time in seconds, overriding the case's end_time")
      ->check(sluice::positive_seconds());
  run->add_option("--set", overrides, "override a case key: key.path=value (repeatable)");
  run->add_option("--stats", stats_path, "write run statistics as JSON to this file");
  const char* device_help =
      "where the loops run (default: the case's model.device, else cpu): cpu, gpu (CUDA; the "
      "wcsph model), emulated (the GPU's steps on the host's threads)";
  run->add_option("--device", device, device_help)->check(sluice::device_name());

  CLI::App* check =
      app.add_subcommand("check", "validate a case and report its size; runs nothing");
  check->add_option("CASE", case_path, "case file (YAML)")->required();
  check->add_option("--set", overrides, "override a case key: key.path=value (repeatable)");
  check->add_option("--device", device, device_help)->check(sluice::device_name());

  sluice::SweepOptions sweep_options;
  CLI::App* sweep = app.add_subcommand(
      "sweep", "run a case for every combination of values; one summary table of the runs");
  sweep->add_option("CASE", sweep_options.case_path, "case file (YAML)")->required();
  sweep
      ->add_option("--set", sweep_options.settings,
                   "key.path=v1,v2,... (an axis of the sweep) or key.path=value (every run)")
      ->required();
  sweep->add_option("--out", sweep_options.out_dir,
                    "output directory (default: out/sweep_CASE_NAME)");
  sweep->add_option("--jobs", sweep_options.jobs, "runs at once (default: one per core)")
      ->check(sluice::at_least_one());
  sweep->add_option("--end", sweep_options.end_time, "end time of every run")
      ->check(sluice::positive_seconds());

  std::vector<std::string> render_args(1);  // OUT, then the options as render.py reads them
  std::string render_field, render_view, render_time;
  int render_width = 0;
  bool render_movie = false;
  CLI::App* render = app.add_subcommand(
      "render", "PNG pictures of a run's frames, and an MP4 with --movie (scripts/render.py)");
  render->add_option("OUT", render_args[0], "a run's output directory")->required();
  render->add_option("--field", render_field,
                     "the field that colours the water (default: velocity)");
  render->add_option("--view", render_view, "side (x-z, the default), top (x-y) or iso")
      ->check(CLI::IsMember({"side", "top", "iso"}));
  render->add_flag("--movie", render_movie, "an MP4 of the pictures too (ffmpeg)");
  render->add_option("--time", render_time,
                     "one picture: the frame nearest this time [s] (default: every frame)");
  render->add_option("--width", render_width, "the pictures' width in pixels (default: 1280)")
      ->check(CLI::Range(16, 16384));

  sluice::CompareOptions compare_options;
  std::string model_list;
  CLI::App* compare = app.add_subcommand(
      "compare", "run a case with several fluid models; one table and plot of their answers");
  compare->add_option("CASE", compare_options.case_path, "case file (YAML)")->required();
  compare->add_option("--models", model_list,
                      "fluid models, comma-separated (default: the case's compare: entries, or "
                      "every model)");
  compare->add_option("--set", compare_options.settings,
                      "override a case key in every run: key.path=value (repeatable)");
  compare->add_option("--out", compare_options.out_dir,
                      "output directory (default: out/compare_CASE_NAME)");
  compare->add_option("--jobs", compare_options.jobs, "runs at once (default: 1, for fair timings)")
      ->check(sluice::at_least_one());
  compare->add_option("--end", compare_options.end_time, "end time of every run")
      ->check(sluice::positive_seconds());

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    fmt::print(stderr, "error: {}\nRun with --help for more information.\n", e.what());
    return sluice::kExitBadInput;
  }

  try {
    if (ranks.split() && (sweep->parsed() || compare->parsed())) {
      throw sluice::InputError(
          "sweep and compare start their runs themselves: start them without mpirun");
    }
    if (render->parsed()) {
      if (!render_field.empty()) render_args.insert(render_args.end(), {"--field", render_field});
      if (!render_view.empty()) render_args.insert(render_args.end(), {"--view", render_view});
      if (render_width > 0)
        render_args.insert(render_args.end(), {"--width", std::to_string(render_width)});
      if (render_movie) render_args.emplace_back("--movie");
      if (!render_time.empty()) render_args.insert(render_args.end(), {"--time", render_time});
      const std::optional<int> code = sluice::run_script("render.py", render_args);
      if (!code) {
        fmt::print(stderr, "error: render: /usr/bin/python3 or scripts/render.py is missing\n");
        return sluice::kExitFailure;
      }
      return *code;
    }
    if (sweep->parsed()) {
      sweep_options.program = sluice::this_program();
      sweep_options.hypre = &hypre;
      return sluice::run_sweep(sweep_options).all_done() ? sluice::kExitOk : sluice::kExitDiverged;
    }
    if (compare->parsed()) {
      compare_options.program = sluice::this_program();
      if (!model_list.empty()) compare_options.models = sluice::split_model_list(model_list);
      compare_options.hypre = &hypre;
      return sluice::run_compare(compare_options).all_done() ? sluice::kExitOk
                                                             : sluice::kExitDiverged;
    }
    sluice::exec::set_thread_count(threads);
    if (!device.empty()) {
      const sluice::io::CaseConfig plain = sluice::io::read_case(case_path, overrides);
      sluice::check_device(plain, device, "--device");
      if (sluice::sets_model_device(plain, device)) overrides.push_back("model.device=" + device);
    }
    const sluice::io::CaseConfig config = sluice::io::read_case(case_path, overrides);
    if (check->parsed()) {
      const auto c = sluice::check_case(config, &hypre);
      if (ranks.rank() != 0) return sluice::kExitOk;
      fmt::print(
          "{}: {}D case '{}' is valid\n  {}: {} ({} fluid, {} wall)\n  bodies: {} ({} "
          "particles)\n  memory: about {} (estimated from the geometry)\n  first time step: {:.4g} "
          "s, limited by {}: about {:.3g} steps to the end time, {:.6g} s\n  {}\n",
          case_path, config.dimension, config.name, c.element_name, c.particles, c.fluid_particles,
          c.wall_particles, c.bodies, c.body_particles, sluice::readable_bytes(c.estimated_bytes),
          c.first_time_step, c.first_time_step_limit, config.end_time / c.first_time_step,
          config.end_time, c.model);
      return sluice::kExitOk;
    }
    sluice::RunOptions options;
    options.out_dir = !resume_dir.empty() ? resume_dir
                      : out_dir.empty()   ? "out/" + config.name
                                          : out_dir;
    options.resume = !resume_dir.empty();
    if (end_time > 0) options.end_time = end_time;
    options.stats_path = stats_path;
    options.live_progress = isatty(fileno(stderr)) != 0;
    options.hypre = &hypre;
    options.ranks = &ranks;
    const auto summary = sluice::run_case(config, options);
    if (ranks.rank() == 0) print_summary(summary);
    return sluice::kExitOk;
  } catch (const sluice::InputError& e) {
    return fail(ranks, sluice::kExitBadInput, e.what());
  } catch (const sluice::DivergenceError& e) {
    return fail(ranks, sluice::kExitDiverged, e.what());
  } catch (const std::exception& e) {
    return fail(ranks, sluice::kExitFailure, e.what());
  }
}
