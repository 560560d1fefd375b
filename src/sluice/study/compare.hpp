// A comparison of fluid models (`sluice compare CASE --models a,b,...`, `sluice.compare` in
// Python): runs one case with several fluid models, each as a child `sluice run` in OUT/MODEL
// with the settings the case's `compare:` gives that model, then writes one table
// (OUT/compare.csv, OUT/compare.md) and draws OUT/compare_*.png.
#pragma once

#include <string>
#include <vector>

#include "sluice/io/compare_table.hpp"
#include "sluice/study/child_runs.hpp"

namespace sluice {

// settings apply to every run, after the model's own; jobs 0: one run at once, so that their
// wall times compare.
struct CompareOptions : StudyOptions {
  std::vector<std::string> models;         // empty: the case's `compare:` entries, or all
  std::string models_option = "--models";  // as an unknown model's message names them
};

struct CompareOutcome {
  std::string out_dir;
  std::vector<io::CompareResult> results;  // one per model, in the order of the models
  bool all_done() const;
};

// Reads and builds every model's case first, as `sluice check` (bad input, an unknown model
// included: InputError before anything runs or is written), then runs them. A run that diverges
// or fails is a row with its status.
CompareOutcome run_compare(const CompareOptions& options);

// "a,b,c" as a list of models (--models).
std::vector<std::string> split_model_list(const std::string& models);

}  // namespace sluice
