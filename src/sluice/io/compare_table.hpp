// The table of `sluice compare`: one row per fluid model with the settings its run took, how it
// ended, its size, its cost, and what it measured: the mean and peak drag and lift on all the
// bodies (OUT/loads.csv) and each probe (OUT/probes.csv), as CSV and as a Markdown table.
#pragma once

#include <string>
#include <vector>

#include "sluice/io/case_config.hpp"
#include "sluice/io/measurements.hpp"

namespace sluice::io {

// The window of the running mean whose largest value is a load's peak [s].
inline constexpr double kPeakWindow = 0.05;

struct CompareResult {
  std::string model;
  std::string settings;  // the compare settings of its run, "; "-joined; "defaults" for none
  std::string status;    // "done", "diverged", "failed (exit N)"
  std::string elements;  // "14364 particles", "6000 cells"; empty when the run did not finish
  Measurements measurements;
};

// What the finished run in `run_dir` measured, from its stats.json, loads.csv (a case with
// bodies) and probes.csv (a case with probes): `steps`, `wall [s]`, `wall per simulated s`;
// `mean drag`, `peak drag`, `mean lift`, `peak lift` over the rows after t = 0 ([N], 2D
// [N/m]; a peak is the largest running mean over kPeakWindow); per probe of `probes`: a water
// height's rise above its start (`NAME rise [m]`), a front's last position (`NAME end [m]`), a
// pressure's peak (`NAME peak [Pa]`). Sets `result.elements` and `result.measurements`. Throws
// std::runtime_error naming a file that cannot be read.
void read_compare_figures(const std::string& run_dir, const std::vector<ProbeConfig>& probes,
                          int dimension, CompareResult& result);

// Columns: model, status, settings, fluid, then every measurement any run has.
std::string compare_table_csv(const std::vector<CompareResult>& results);
std::string compare_table_markdown(const std::vector<CompareResult>& results);

}  // namespace sluice::io
