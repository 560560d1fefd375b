// F3's series and figures as VALIDATION.md defines them (validation/kleefsman_figures.py holds
// the same for the docs' table): a 5 ms running mean of each pressure, first crossings, and RMS
// differences at the experiment's times.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "physics_support.hpp"

namespace sluice::testing {

// Columns of one record by name ("time", "P1" ... "P8", and the gauges as the case names its
// probes: "g496", "g992", "g1488", "g2638").
using Series = std::map<std::string, std::vector<double>>;

// A column of validation/data's F3 files named as the case names its probe: time_s -> time,
// P1_Pa -> P1, h_x1.488_m -> g1488.
inline std::string probe_name(const std::string& column) {
  if (column == "time_s") return std::string("time");
  if (column.rfind("h_x", 0) == 0) {
    char name[24];  // snprintf: GCC 12 warns falsely on "g" + std::to_string at -O3
    std::snprintf(name, sizeof name, "g%ld", std::lround(1000 * std::stod(column.substr(3))));
    return name;
  }
  return column.substr(0, column.find('_'));
}

// A tab-separated file of validation/data with '#' comments and one header line, its columns
// renamed by probe_name.
inline Series read_kleefsman_tsv(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::string> names;
  Series out;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    if (names.empty()) {
      for (std::string column; fields >> column;) names.push_back(probe_name(column));
      continue;
    }
    double value = 0;
    for (const std::string& name : names) {
      if (fields >> value) out[name].push_back(value);
    }
  }
  return out;
}

// The centred mean over the n = round(width / dt) samples around each (dt the median sample
// spacing, zeros beyond the ends), as numpy's convolve(mode="same") takes it.
inline std::vector<double> running_mean(const std::vector<double>& t, const std::vector<double>& v,
                                        double width = 0.005) {
  std::vector<double> dt(t.size() - 1);
  for (std::size_t k = 0; k + 1 < t.size(); ++k) dt[k] = t[k + 1] - t[k];
  std::nth_element(dt.begin(), dt.begin() + static_cast<std::ptrdiff_t>(dt.size() / 2), dt.end());
  const auto n = std::max<long>(1, std::lround(width / dt[dt.size() / 2]));
  std::vector<double> out(v.size(), 0.0);
  for (long i = 0; i < static_cast<long>(v.size()); ++i) {
    for (long j = i - n / 2; j <= i + (n - 1) / 2; ++j) {
      if (j >= 0 && j < static_cast<long>(v.size())) out[i] += v[j] / n;
    }
  }
  return out;
}

// The first time at which v exceeds level, linear between samples; NaN if it never does.
inline double first_crossing(const std::vector<double>& t, const std::vector<double>& v,
                             double level) {
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (v[k] <= level) continue;
    if (k == 0) return t[0];
    return t[k - 1] + (level - v[k - 1]) / (v[k] - v[k - 1]) * (t[k] - t[k - 1]);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

// RMS of a series against the reference at the reference's times in [0, end]; a pressure
// (name "P...") smoothed first on both sides.
inline double rms_against(const Series& series, const Series& reference, const std::string& name,
                          double end) {
  const bool pressure = name[0] == 'P';
  const auto& t = series.at("time");
  const auto& tr = reference.at("time");
  const auto mine = pressure ? running_mean(t, series.at(name)) : series.at(name);
  const auto theirs = pressure ? running_mean(tr, reference.at(name)) : reference.at(name);
  double sum2 = 0;
  int count = 0;
  for (std::size_t k = 0; k < tr.size() && tr[k] <= end; ++k) {
    const double e = interpolate(t, mine, tr[k]) - theirs[k];
    sum2 += e * e;
    ++count;
  }
  return std::sqrt(sum2 / count);
}

}  // namespace sluice::testing
