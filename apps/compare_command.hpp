// `sluice compare CASE --models a,b,...`: runs one case with several fluid models, each as a
// child `sluice run` in OUT/MODEL with the settings the case's `compare:` gives that model,
// then writes one table (OUT/compare.csv, OUT/compare.md) and draws OUT/compare_*.png.
#pragma once

#include <string>
#include <vector>

namespace sluice {

class HypreSession;  // linear/hypre_session.hpp

struct CompareOptions {
  std::string case_path;
  std::string models;                 // "a,b,..."; empty: the case's `compare:` entries, or all
  std::vector<std::string> settings;  // --set for every run, after the model's own settings
  std::string out_dir;                // default: out/compare_CASE_NAME
  int jobs = 1;                       // runs at once: one, so that their wall times compare
  double end_time = 0;                // 0 = the case's
  std::string self;                   // this program, to start the runs
  HypreSession* hypre = nullptr;      // the process's, for the checks (sim/runner.hpp)
};

// Reads and builds every model's case first, as `sluice check` (bad input, an unknown model
// included: InputError before anything runs or is written), then runs them. Returns the exit
// code: 0 when every run finished, 3 when one diverged or failed.
int run_compare(const CompareOptions& options);

}  // namespace sluice
