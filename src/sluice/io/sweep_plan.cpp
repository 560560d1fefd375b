#include "sluice/io/sweep_plan.hpp"

#include "sluice/core/errors.hpp"

namespace sluice::io {

namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// The key paths of a setting's key, joined by '+'.
std::vector<std::string> joined_keys(const std::string& key) {
  std::vector<std::string> keys;
  std::size_t start = 0;
  while (true) {
    const auto plus = key.find('+', start);
    keys.push_back(trimmed(key.substr(start, plus - start)));
    if (plus == std::string::npos) return keys;
    start = plus + 1;
  }
}

}  // namespace

SweepSetting parse_sweep_setting(const std::string& assignment) {
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0) {
    throw InputError("--set " + assignment, 0, "",
                     "expected KEY.PATH=VALUE or KEY.PATH=V1,V2,..., for example "
                     "model.artificial_viscosity=0.01,0.02");
  }
  SweepSetting setting;
  setting.key = assignment.substr(0, equals);
  for (const std::string& key : joined_keys(setting.key)) {
    if (trimmed(key).empty()) {
      throw InputError("--set " + setting.key, 0, setting.key,
                       "an empty key path among those joined by '+'");
    }
  }
  const std::string text = assignment.substr(equals + 1);
  int depth = 0;
  std::string value;
  const auto close_value = [&] {
    const std::string v = trimmed(value);
    if (v.empty()) {
      throw InputError("--set " + setting.key, 0, setting.key,
                       "empty value in the list '" + text + "'");
    }
    setting.values.push_back(v);
    value.clear();
  };
  char quote = 0;  // within a quoted YAML string: '"' or '\'', whose commas are its own
  for (const char c : text) {
    if (quote != 0) {
      if (c == quote) quote = 0;
      value += c;
      continue;
    }
    if (c == '"' || c == '\'') quote = c;
    if (c == '[' || c == '{') ++depth;
    if (c == ']' || c == '}') --depth;
    if (c == ',' && depth == 0) {
      close_value();
      continue;
    }
    value += c;
  }
  close_value();
  return setting;
}

std::vector<SweepRun> sweep_runs(const std::vector<SweepSetting>& settings) {
  std::vector<SweepRun> runs{SweepRun{}};
  for (const SweepSetting& s : settings) {
    std::vector<SweepRun> next;
    for (const SweepRun& run : runs) {
      for (const std::string& value : s.values) {
        SweepRun r = run;
        for (const std::string& key : joined_keys(s.key)) r.overrides.push_back(key + "=" + value);
        if (s.values.size() > 1) r.values.push_back(value);
        next.push_back(std::move(r));
      }
    }
    runs = std::move(next);
  }
  return runs;
}

std::vector<std::string> sweep_axes(const std::vector<SweepSetting>& settings) {
  std::vector<std::string> keys;
  for (const SweepSetting& s : settings) {
    if (s.values.size() > 1) keys.push_back(s.key);
  }
  return keys;
}

}  // namespace sluice::io
