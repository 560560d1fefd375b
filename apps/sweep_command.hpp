// `sluice sweep CASE --set KEY=V1,V2,... [--set ...]`: runs the case for every combination of
// the values, each as a child `sluice run` in OUT/run_NNN, several at once where the cores
// allow, then writes OUT/summary.csv and OUT/summary.md and draws OUT/summary_*.png.
#pragma once

#include <string>
#include <vector>

namespace sluice {

class HypreSession;  // linear/hypre_session.hpp

struct SweepOptions {
  std::string case_path;
  std::vector<std::string> settings;  // the --set arguments
  std::string out_dir;                // default: out/sweep_CASE_NAME
  int jobs = 0;                       // runs at once; 0 = as many as cores, at most the runs
  double end_time = 0;                // 0 = the case's
  std::string self;                   // this program, to start the runs
  HypreSession* hypre = nullptr;      // the process's, for the checks (sim/runner.hpp)
};

// Checks every combination first, as `sluice check` (bad input: InputError before anything
// runs or is written), then runs them. Returns the exit code: 0 when every run finished, 3 when one
// diverged or failed.
int run_sweep(const SweepOptions& options);

}  // namespace sluice
