#include "sluice/io/compare_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "sluice/io/csv_table.hpp"
#include "sluice/io/sweep_table.hpp"
#include "sluice/io/text_table.hpp"

namespace sluice::io {

namespace {

// The column of `table` named `name`, or an error naming the file.
std::vector<double> column_of(const CsvTable& table, const std::string& name,
                              const std::string& path) {
  const auto index = table.column(name);
  if (!index) throw std::runtime_error(path + ": no column '" + name + "'");
  return table.values(*index);
}

// The column of probes.csv that belongs to probe `name`: "NAME [unit]".
std::vector<double> probe_column(const CsvTable& table, const std::string& name,
                                 const std::string& path) {
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    if (table.columns[c].rfind(name + " [", 0) == 0) return table.values(c);
  }
  throw std::runtime_error(path + ": no column for the probe '" + name + "'");
}

// The largest of the running means of `values` over `window` seconds centred on each time:
// a particle model's forces carry acoustic spikes from step to step that are not the load.
double peak_of_running_mean(const std::vector<double>& time, const std::vector<double>& values,
                            double window) {
  double peak = -std::numeric_limits<double>::infinity();
  std::size_t first = 0, last = 0;  // the rows within the window: [first, last)
  double sum = 0;
  for (std::size_t k = 0; k < values.size(); ++k) {
    while (last < values.size() && time[last] <= time[k] + window / 2) sum += values[last++];
    while (time[first] < time[k] - window / 2) sum -= values[first++];
    peak = std::max(peak, sum / double(last - first));
  }
  return peak;
}

void add_loads(const std::string& path, int dimension, Measurements& out) {
  const CsvTable loads = read_csv_table(path);
  const std::vector<double> all_time = column_of(loads, "time", path);
  const std::string unit = dimension == 2 ? "N/m" : "N";
  for (const char* load : {"drag", "lift"}) {
    const std::vector<double> all = column_of(loads, std::string("all_bodies_") + load, path);
    std::vector<double> time, later;  // the forces after t = 0, where they have been evaluated
    for (std::size_t k = 0; k < all.size(); ++k) {
      if (all_time[k] > 0) {
        time.push_back(all_time[k]);
        later.push_back(all[k]);
      }
    }
    if (later.empty()) continue;
    const double mean = std::accumulate(later.begin(), later.end(), 0.0) / double(later.size());
    out.emplace_back(fmt::format("mean {} [{}]", load, unit), mean);
    out.emplace_back(fmt::format("peak {} [{}]", load, unit),
                     peak_of_running_mean(time, later, kPeakWindow));
  }
}

void add_probes(const std::string& path, const std::vector<ProbeConfig>& probes,
                Measurements& out) {
  const CsvTable table = read_csv_table(path);
  for (const ProbeConfig& probe : probes) {
    const std::vector<double> v = probe_column(table, probe.name, path);
    if (v.empty()) continue;
    switch (probe.kind) {
      case ProbeKind::kWaterHeight:
        out.emplace_back(probe.name + " rise [m]",
                         *std::max_element(v.begin(), v.end()) - v.front());
        break;
      case ProbeKind::kSurgeFront:
        out.emplace_back(probe.name + " end [m]", v.back());
        break;
      case ProbeKind::kPressure:
        out.emplace_back(probe.name + " peak [Pa]", *std::max_element(v.begin(), v.end()));
        break;
      case ProbeKind::kBoundaryFlux:
        out.emplace_back(probe.name + " end [" + probe.unit + "]", v.back());
        break;
    }
  }
}

TextTable cells(const std::vector<CompareResult>& results) {
  std::vector<const Measurements*> runs;
  for (const CompareResult& r : results) runs.push_back(&r.measurements);
  const std::vector<std::string> names = measurement_names(runs);
  TextTable rows;
  std::vector<std::string> header{"model", "status", "settings", "fluid"};
  header.insert(header.end(), names.begin(), names.end());
  rows.push_back(header);
  for (const CompareResult& r : results) {
    std::vector<std::string> row{r.model, r.status, r.settings, r.elements};
    for (const std::string& name : names) row.push_back(measurement_cell(r.measurements, name));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

void read_compare_figures(const std::string& run_dir, const std::vector<ProbeConfig>& probes,
                          int dimension, CompareResult& result) {
  const YAML::Node stats = load_run_statistics(run_dir + "/stats.json");
  result.elements = fmt::format("{} {}", stats["fluid_particles"].as<std::size_t>(),
                                stats["element_name"].as<std::string>());
  Measurements& out = result.measurements;
  out.clear();
  out.emplace_back("steps", stats["steps"].as<double>());
  out.emplace_back("wall [s]", stats["wall_seconds"].as<double>());
  out.emplace_back("wall per simulated s", stats["wall_seconds_per_simulated_second"].as<double>());
  if (stats["bodies"].as<int>() > 0) add_loads(run_dir + "/loads.csv", dimension, out);
  if (!probes.empty()) add_probes(run_dir + "/probes.csv", probes, out);
}

std::string compare_table_csv(const std::vector<CompareResult>& results) {
  return table_csv(cells(results));
}

std::string compare_table_markdown(const std::vector<CompareResult>& results) {
  return table_markdown(cells(results));
}

}  // namespace sluice::io
