// The summary of a parameter sweep: one row per run with the swept values, how the run ended
// and its measurements (the model's figures and each probe at the end, from the run's
// --stats file), as CSV and as a Markdown table.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <utility>
#include <vector>

#include "sluice/io/measurements.hpp"

namespace sluice::io {

struct SweepResult {
  std::vector<std::string> values;  // one per swept key
  std::string status;               // "done", "diverged", "failed (exit N)"
  Measurements measurements;        // empty when the run did not finish
};

// A run's --stats JSON. Throws std::runtime_error naming the file if it cannot be read.
YAML::Node load_run_statistics(const std::string& stats_path);

// The measurements of a finished run from its --stats JSON: the model's figures
// (`fluid_counters`), each probe at the end (`final_probes`), then `steps` and `wall_seconds`.
// Throws std::runtime_error naming the file if it cannot be read.
Measurements read_run_measurements(const std::string& stats_path);

// Columns: run, the swept keys, status, then every measurement that any run has, in the order
// they first appear; a run without one leaves it empty.
std::string sweep_table_csv(const std::vector<std::string>& keys,
                            const std::vector<SweepResult>& results);
std::string sweep_table_markdown(const std::vector<std::string>& keys,
                                 const std::vector<SweepResult>& results);

}  // namespace sluice::io
