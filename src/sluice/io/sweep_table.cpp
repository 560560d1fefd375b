#include "sluice/io/sweep_table.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace sluice::io {

namespace {

void add_map(const YAML::Node& map, Measurements& out) {
  if (!map || !map.IsMap()) return;
  for (const auto& entry : map)
    out.emplace_back(entry.first.as<std::string>(), entry.second.as<double>());
}

std::vector<std::string> measurement_names(const std::vector<SweepResult>& results) {
  std::vector<std::string> names;
  for (const SweepResult& r : results) {
    for (const auto& m : r.measurements) {
      if (std::find(names.begin(), names.end(), m.first) == names.end()) names.push_back(m.first);
    }
  }
  return names;
}

std::optional<double> value_of(const SweepResult& r, const std::string& name) {
  for (const auto& m : r.measurements) {
    if (m.first == name) return m.second;
  }
  return std::nullopt;
}

// One table as rows of cells, the header first.
std::vector<std::vector<std::string>> cells(const std::vector<std::string>& keys,
                                            const std::vector<SweepResult>& results) {
  const std::vector<std::string> names = measurement_names(results);
  std::vector<std::vector<std::string>> rows;
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
    for (const std::string& name : names) {
      const auto v = value_of(r, name);
      row.push_back(v ? fmt::format("{:.6g}", *v) : "");
    }
    rows.push_back(row);
  }
  return rows;
}

std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  quoted += '"';
  return quoted;
}

}  // namespace

Measurements read_run_measurements(const std::string& stats_path) {
  YAML::Node stats;
  try {
    stats = YAML::LoadFile(stats_path);  // JSON is YAML
  } catch (const YAML::Exception& e) {
    throw std::runtime_error(stats_path + ": cannot read the run statistics: " + e.msg);
  }
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
  std::string text;
  for (const auto& row : cells(keys, results)) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (c > 0) text += ',';
      text += csv_cell(row[c]);
    }
    text += '\n';
  }
  return text;
}

std::string sweep_table_markdown(const std::vector<std::string>& keys,
                                 const std::vector<SweepResult>& results) {
  const auto rows = cells(keys, results);
  std::string text;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    text += "|";
    for (const std::string& cell : rows[r]) {
      text += ' ';
      text += cell;
      text += " |";
    }
    text += "\n";
    if (r == 0) {
      text += "|";
      for (std::size_t c = 0; c < rows[r].size(); ++c) text += "---|";
      text += "\n";
    }
  }
  return text;
}

}  // namespace sluice::io
