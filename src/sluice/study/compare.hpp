// A comparison of fluid models (`sluice compare CASE --models a,b,...`, `sluice.compare` in
// Python): runs one case with several fluid models, each as a child `sluice run` in OUT/MODEL
// with the settings the case's `compare:` gives that model, then writes one table
// (OUT/compare.csv, OUT/compare.md) and draws OUT/compare_*.png.
#pragma once

#include <string>
#include <vector>

#include "sluice/io/compare_table.hpp"

namespace sluice {

class HypreSession;  // linear/hypre_session.hpp

struct CompareOptions {
  std::string case_path;
  std::vector<std::string> models;    // empty: the case's `compare:` entries, or all
  std::vector<std::string> settings;  // --set for every run, after the model's own settings
  std::string out_dir;                // default: out/compare_CASE_NAME
  int jobs = 1;                       // runs at once: one, so that their wall times compare
  double end_time = 0;                // 0 = the case's
  std::string program;                // the sluice executable, which runs each case
  HypreSession* hypre = nullptr;      // the process's, for the checks (sim/runner.hpp)
  bool report = true;                 // a line on stdout as each run ends
};

struct CompareOutcome {
  std::string out_dir;
  std::vector<io::CompareResult> results;  // one per model, in the order they ran
  bool all_done() const;
};

// Reads and builds every model's case first, as `sluice check` (bad input, an unknown model
// included: InputError before anything runs or is written), then runs them. A run that diverges
// or fails is a row with its status.
CompareOutcome run_compare(const CompareOptions& options);

// "a,b,c" as a list of models (--models).
std::vector<std::string> split_model_list(const std::string& models);

}  // namespace sluice
