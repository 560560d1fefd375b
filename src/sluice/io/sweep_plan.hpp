// The runs of a parameter sweep (`sluice sweep CASE --set KEY=V1,V2,...`): each --set with
// several values is an axis, one with a single value is applied to every run, and the runs are
// every combination of the axes' values. A --set of keys joined by '+' (KEY1+KEY2=V1,V2) sets
// each value at every one of them: one axis for quantities the case states in several places
// (a channel's depth: its block's top, its inlet's and its outlet's depth).
#pragma once

#include <string>
#include <vector>

namespace sluice::io {

struct SweepSetting {
  std::string key;                  // the key path, as for --set, or several joined by '+'
  std::vector<std::string> values;  // each a YAML value, as --set takes it
};

struct SweepRun {
  std::vector<std::string> overrides;  // "KEY=VALUE" for every setting, in the given order
  std::vector<std::string> values;     // the value of each axis (settings with 2+ values)
};

// Splits "KEY=V1,V2,..." at the commas outside brackets, braces and quotes, so that
// `fluid.blocks.0.max=[0.5, 1],[0.6, 1]` gives two values and `name="a, b",c` two. Throws
// InputError naming the --set on a missing key, an empty key between '+', or an empty value.
SweepSetting parse_sweep_setting(const std::string& assignment);

// Every combination, the last axis varying fastest.
std::vector<SweepRun> sweep_runs(const std::vector<SweepSetting>& settings);

// The keys of the axes, in order.
std::vector<std::string> sweep_axes(const std::vector<SweepSetting>& settings);

}  // namespace sluice::io
