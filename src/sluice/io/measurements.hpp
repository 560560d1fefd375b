// Named figures of a run (a model's counters, probes, timings), as the tables of `sluice sweep`
// and `sluice compare` list them: one column per name, empty where a run lacks it.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace sluice::io {

using Measurements = std::vector<std::pair<std::string, double>>;

// Every name that any of `runs` has, in the order they first appear.
inline std::vector<std::string> measurement_names(const std::vector<const Measurements*>& runs) {
  std::vector<std::string> names;
  for (const Measurements* run : runs) {
    for (const auto& m : *run) {
      if (std::find(names.begin(), names.end(), m.first) == names.end()) names.push_back(m.first);
    }
  }
  return names;
}

// The value named `name` to 6 significant digits, or "" when the run lacks it.
inline std::string measurement_cell(const Measurements& run, const std::string& name) {
  for (const auto& m : run) {
    if (m.first == name) return fmt::format("{:.6g}", m.second);
  }
  return "";
}

}  // namespace sluice::io
