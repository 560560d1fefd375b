#include "sluice/study/compare.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "sluice/core/errors.hpp"
#include "sluice/io/compare_table.hpp"
#include "sluice/io/vtk_writer.hpp"
#include "sluice/io/yaml_reader.hpp"
#include "sluice/models/shipped_models.hpp"
#include "sluice/sim/runner.hpp"

namespace sluice {

namespace {

std::vector<std::string> model_names(int dimension) {
  return dimension == 2 ? shipped_models<2>().names() : shipped_models<3>().names();
}

// The models to run: --models, else the case's `compare:` entries, else every model.
std::vector<std::string> models_to_run(const CompareOptions& o, const io::CaseConfig& base,
                                       const std::vector<std::string>& known) {
  for (const io::CompareEntry& entry : base.compare) {
    if (std::find(known.begin(), known.end(), entry.model) == known.end()) {
      throw InputError(base.file(), entry.line, "compare." + entry.model,
                       io::unknown_choice("fluid model", entry.model, known));
    }
  }
  std::vector<std::string> models;
  if (!o.models.empty()) {
    for (const std::string& name : o.models) {
      if (std::find(known.begin(), known.end(), name) == known.end()) {
        throw InputError(o.models_option + ": " + io::unknown_choice("fluid model", name, known));
      }
      if (std::find(models.begin(), models.end(), name) == models.end()) models.push_back(name);
    }
  } else if (!base.compare.empty()) {
    for (const io::CompareEntry& entry : base.compare) models.push_back(entry.model);
  } else {
    models = known;
  }
  return models;
}

struct ModelRun {
  std::string model;
  std::vector<std::string> overrides;  // --set, in order
  std::string settings;                // as the table states them
};

// A model runs with its `compare:` settings; without an entry, with its defaults, but for the
// case's own model, which keeps the case's `model:` mapping.
ModelRun model_run(const std::string& model, const io::CaseConfig& base,
                   const std::vector<std::string>& user_settings) {
  ModelRun run{model, {}, ""};
  const auto entry = std::find_if(base.compare.begin(), base.compare.end(),
                                  [&](const io::CompareEntry& e) { return e.model == model; });
  const bool own = model == base.model_name;
  if (entry == base.compare.end() || !entry->sets_model) {
    if (!own) run.overrides.push_back("model={name: " + model + "}");
  }
  if (entry != base.compare.end()) {
    run.overrides.insert(run.overrides.end(), entry->settings.begin(), entry->settings.end());
    for (const std::string& s : entry->settings)
      run.settings += (run.settings.empty() ? "" : "; ") + s;
  }
  if (run.settings.empty()) run.settings = own ? "the case's" : "defaults";
  run.overrides.insert(run.overrides.end(), user_settings.begin(), user_settings.end());
  return run;
}

}  // namespace

std::vector<std::string> split_model_list(const std::string& models) {
  std::vector<std::string> names;
  std::size_t start = 0;
  while (start <= models.size()) {
    const std::size_t comma = std::min(models.find(',', start), models.size());
    names.push_back(models.substr(start, comma - start));
    start = comma + 1;
  }
  return names;
}

bool CompareOutcome::all_done() const {
  return std::all_of(results.begin(), results.end(),
                     [](const io::CompareResult& r) { return r.status == "done"; });
}

CompareOutcome run_compare(const CompareOptions& o) {
  const io::CaseConfig base = io::read_case(o.case_path, o.settings);
  const std::vector<std::string> known = model_names(base.dimension);
  const std::vector<std::string> models = models_to_run(o, base, known);
  // Every model's case is read and built (the model checks its own keys) before anything runs
  // or is written, as `sluice check` would.
  std::vector<ModelRun> runs;
  for (const std::string& model : models) {
    runs.push_back(model_run(model, base, o.settings));
    check_case(io::read_case(o.case_path, runs.back().overrides), o.hypre);
  }
  if (o.checked) o.checked();
  CompareOutcome outcome{o.out_dir.empty() ? "out/compare_" + base.name : o.out_dir, {}};
  const std::string& out_dir = outcome.out_dir;
  create_study_directory(out_dir);
  const int jobs = std::clamp(o.jobs > 0 ? o.jobs : 1, 1, static_cast<int>(runs.size()));
  const int threads = threads_per_run(jobs);
  report_study_start(o, fmt::format("compare: {} models on {}", runs.size(), o.case_path), jobs,
                     threads, out_dir);

  std::vector<io::CompareResult>& results = outcome.results;
  results.resize(runs.size());
  std::vector<ChildRun> children;
  for (const ModelRun& run : runs)
    children.push_back(sluice_run(o.program, o.case_path, out_dir + "/" + run.model, threads,
                                  o.end_time, run.overrides));
  std::size_t finished = 0;
  run_children(
      children, jobs,
      [&](std::size_t k, const ChildOutcome& child) {
        io::CompareResult& r = results[k];
        r.model = runs[k].model;
        r.settings = runs[k].settings;
        r.status = child.status;
        const std::string dir = out_dir + "/" + r.model;
        if (r.status == "done") read_compare_figures(dir, base.probes, base.dimension, r);
        report_run_end(o, ++finished, runs.size(), r.model, r.status, child.seconds, dir);
      },
      o.stop_requested);
  io::write_file_atomically(out_dir + "/compare.csv", io::compare_table_csv(results));
  io::write_file_atomically(out_dir + "/compare.md", io::compare_table_markdown(results));
  if (o.report) {
    fmt::print("table: {0}/compare.csv, {0}/compare.md\n", out_dir);
    std::fflush(stdout);
  }
  std::vector<std::string> plot_args{out_dir};
  plot_args.insert(plot_args.end(), models.begin(), models.end());
  draw_plots("plot_compare.py", plot_args, o.report);
  return outcome;
}

}  // namespace sluice
