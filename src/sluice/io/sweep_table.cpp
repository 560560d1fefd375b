#include "sluice/io/sweep_table.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <stdexcept>

#include "sluice/io/text_table.hpp"

namespace sluice::io {

namespace {

void add_map(const YAML::Node& map, Measurements& out) {
  if (!map || !map.IsMap()) return;
  for (const auto& entry : map)
    out.emplace_back(entry.first.as<std::string>(), entry.second.as<double>());
}

// One table as rows of cells, the header first.
TextTable cells(const std::vector<std::string>& keys, const std::vector<SweepResult>& results) {
  std::vector<const Measurements*> runs;
  for (const SweepResult& r : results) runs.push_back(&r.measurements);
  const std::vector<std::string> names = measurement_names(runs);
  TextTable rows;
  std::vector<std::string> header{"run"};
  header.insert(header.end(), keys.begin(), keys.end());
  header.push_back("status");
  header.insert(header.end(), names.begin(), names.end());
  rows.push_back(header);
  for (std::size_t k = 0; k < results.size(); ++k) {
    const SweepResult& r = results[k];
    std::vector<std::string> row{std::to_string(k + 1)};
    row.insert(row.end(), r.values.begin(), r.values.end());
    row.push_back(r.status);
    for (const std::string& name : names) row.push_back(measurement_cell(r.measurements, name));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

YAML::Node load_run_statistics(const std::string& stats_path) {
  try {
    return YAML::LoadFile(stats_path);  // JSON is YAML
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(stats_path + ": cannot read the run statistics: " + e.msg);
  }
}

Measurements read_run_measurements(const std::string& stats_path) {
  const YAML::Node stats = load_run_statistics(stats_path);
  Measurements out;
  add_map(stats["fluid_counters"], out);
  add_map(stats["final_probes"], out);
  for (const char* key : {"steps", "wall_seconds"}) {
    if (stats[key]) out.emplace_back(key, stats[key].as<double>());
  }
  return out;
}

std::string sweep_table_csv(const std::vector<std::string>& keys,
                            const std::vector<SweepResult>& results) {
  return table_csv(cells(keys, results));
}

std::string sweep_table_markdown(const std::vector<std::string>& keys,
                                 const std::vector<SweepResult>& results) {
  return table_markdown(cells(keys, results));
}

}  // namespace sluice::io
