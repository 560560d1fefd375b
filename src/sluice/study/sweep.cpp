#include "sluice/study/sweep.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "sluice/core/errors.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/io/sweep_plan.hpp"
#include "sluice/io/sweep_table.hpp"
#include "sluice/io/vtk_writer.hpp"
#include "sluice/sim/runner.hpp"

namespace sluice {

bool SweepOutcome::all_done() const {
  return std::all_of(results.begin(), results.end(),
                     [](const io::SweepResult& r) { return r.status == "done"; });
}

SweepOutcome run_sweep(const SweepOptions& o) {
  std::vector<io::SweepSetting> settings;
  for (const std::string& s : o.settings) settings.push_back(io::parse_sweep_setting(s));
  const std::vector<io::SweepRun> runs = io::sweep_runs(settings);
  const std::vector<std::string> keys = io::sweep_axes(settings);
  // Every combination is read and built (the model checks its own keys) before anything runs
  // or is written, as `sluice check` would.
  std::string name;
  for (const io::SweepRun& run : runs) {
    const io::CaseConfig config = io::read_case(o.case_path, run.overrides);
    check_case(config, o.hypre);
    name = config.name;
  }
  if (o.checked) o.checked();
  SweepOutcome outcome{o.out_dir.empty() ? "out/sweep_" + name : o.out_dir, keys, {}};
  const std::string& out_dir = outcome.out_dir;
  create_study_directory(out_dir);
  const int jobs =
      std::clamp(o.jobs > 0 ? o.jobs : threads_per_run(1), 1, static_cast<int>(runs.size()));
  const int threads = threads_per_run(jobs);
  report_study_start(o, fmt::format("sweep: {} runs of {}", runs.size(), o.case_path), jobs,
                     threads, out_dir);

  std::vector<io::SweepResult>& results = outcome.results;
  results.resize(runs.size());
  const auto dir_of = [&](std::size_t k) { return fmt::format("{}/run_{:03d}", out_dir, k + 1); };
  std::vector<ChildRun> children;
  for (std::size_t k = 0; k < runs.size(); ++k)
    children.push_back(
        sluice_run(o.program, o.case_path, dir_of(k), threads, o.end_time, runs[k].overrides));
  std::size_t finished = 0;
  run_children(
      children, jobs,
      [&](std::size_t k, const ChildOutcome& child) {
        io::SweepResult& r = results[k];
        r.values = runs[k].values;
        r.status = child.status;
        if (r.status == "done")
          r.measurements = io::read_run_measurements(dir_of(k) + "/stats.json");
        std::string label = fmt::format("run_{:03d}", k + 1);
        for (std::size_t a = 0; a < keys.size(); ++a)
          label += fmt::format(" {}={}", keys[a], r.values[a]);
        report_run_end(o, ++finished, runs.size(), label, r.status, child.seconds, dir_of(k));
      },
      o.stop_requested);
  io::write_file_atomically(out_dir + "/summary.csv", io::sweep_table_csv(keys, results));
  io::write_file_atomically(out_dir + "/summary.md", io::sweep_table_markdown(keys, results));
  if (o.report) {
    fmt::print("summary: {0}/summary.csv, {0}/summary.md\n", out_dir);
    std::fflush(stdout);
  }
  draw_plots("plot_sweep.py", {out_dir}, o.report);
  return outcome;
}

}  // namespace sluice
