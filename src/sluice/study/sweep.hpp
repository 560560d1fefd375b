// A parameter sweep (`sluice sweep CASE --set KEY=V1,V2,...`, `sluice.sweep` in Python): runs
// the case for every combination of the values, each as a child `sluice run` in OUT/run_NNN,
// several at once where the cores allow, then writes OUT/summary.csv and OUT/summary.md and
// draws OUT/summary_*.png.
#pragma once

#include <string>
#include <vector>

#include "sluice/io/sweep_table.hpp"
#include "sluice/study/child_runs.hpp"

namespace sluice {

// jobs 0: as many runs at once as cores, at most the runs.
struct SweepOptions : StudyOptions {};

struct SweepOutcome {
  std::string out_dir;
  std::vector<std::string> keys;         // the swept keys, one per axis
  std::vector<io::SweepResult> results;  // one per run, in the order of run_NNN
  bool all_done() const;
};

// Checks every combination first, as `sluice check` (bad input: InputError before anything
// runs or is written), then runs them. A run that diverges or fails is a row with its status.
SweepOutcome run_sweep(const SweepOptions& options);

}  // namespace sluice
