#include "sluice/io/boundary_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "sluice/core/smooth_ramp.hpp"
#include "sluice/io/csv_table.hpp"

namespace sluice::io {

double BoundaryConfig::speed_at(double time) const {
  const double share = smooth_ramp(time, ramp_time).share;
  if (speed_table.empty()) return share * mean_speed;
  if (time <= speed_table.front().first) return share * speed_table.front().second;
  if (time >= speed_table.back().first) return share * speed_table.back().second;
  const auto after = std::upper_bound(speed_table.begin(), speed_table.end(), time,
                                      [](double t, const auto& row) { return t < row.first; });
  const auto before = after - 1;
  const double s = (time - before->first) / (after->first - before->first);
  return share * ((1 - s) * before->second + s * after->second);
}

std::vector<std::pair<double, double>> read_speed_table(const std::string& path,
                                                        const MapReader& owner,
                                                        const std::string& key) {
  CsvTable table;
  try {
    table = read_csv_table(path);
  } catch (const std::runtime_error& e) {
    owner.fail(key, fmt::format("cannot read the speed table: {}", e.what()));
  }
  const auto time = table.column("time"), speed = table.column("speed");
  if (!time || !speed) {
    owner.fail(key, fmt::format("speed table '{}' line 1: expected the columns time, speed", path));
  }
  std::vector<std::pair<double, double>> rows;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const double t = table.rows[r][*time], v = table.rows[r][*speed];
    if (!std::isfinite(t) || !std::isfinite(v)) {
      owner.fail(key, fmt::format("speed table '{}' row {}: not a finite number", path, r + 1));
    }
    if (!rows.empty() && !(t > rows.back().first)) {
      owner.fail(key, fmt::format("speed table '{}' row {}: time {} does not come after {} (the "
                                  "rows must be sorted in time)",
                                  path, r + 1, t, rows.back().first));
    }
    rows.emplace_back(t, v);
  }
  if (rows.empty()) owner.fail(key, fmt::format("speed table '{}' has no rows", path));
  return rows;
}

BoundaryConfig read_boundary(MapReader& map, std::size_t index, const AxisBox& domain,
                             int dimension, const std::string& case_file) {
  BoundaryConfig b;
  b.line = map.line();
  b.key = fmt::format("boundaries[{}]", index);
  // A required key that must be one of `choices`.
  auto required_choice = [&](const std::string& key, const std::string& what,
                             const std::vector<std::string>& choices) {
    const std::string value = map.required<std::string>(key);
    if (std::find(choices.begin(), choices.end(), value) == choices.end())
      map.fail_choice(key, what, value, choices);
    return value;
  };
  const std::string type = required_choice("type", "boundary type", {"inlet", "outlet"});
  b.kind = type == "inlet" ? BoundaryKind::kInlet : BoundaryKind::kOutlet;
  b.name = map.optional<std::string>("name", fmt::format("{}{}", type, index));
  const std::vector<std::string> sides =
      dimension == 2 ? std::vector<std::string>{"x-", "x+", "z-", "z+"}
                     : std::vector<std::string>{"x-", "x+", "y-", "y+", "z-", "z+"};
  const std::string side = required_choice("side", "side of the domain", sides);
  b.axis = side[0] - 'x';
  b.upper = side[1] == '+';
  if (map.has("depth")) {
    if (b.axis == 2) map.fail("depth", "a side across the vertical (z) has no depth");
    b.depth = map.required_positive("depth");
    if (*b.depth > domain.max[2] - domain.min[2]) {
      map.fail("depth",
               fmt::format("exceeds the domain's height ({} m)", domain.max[2] - domain.min[2]));
    }
  }
  if (b.kind == BoundaryKind::kInlet) {
    b.profile = map.optional_choice("profile", "uniform", "inlet profile",
                                    {"uniform", "parabolic"}) == "uniform"
                    ? InletProfile::kUniform
                    : InletProfile::kParabolic;
    if (map.has("mean_speed") == map.has("speed_table")) {
      map.fail(map.has("mean_speed") ? "speed_table" : "mean_speed",
               "an inlet takes one of mean_speed or speed_table");
    }
    if (map.has("mean_speed")) {
      b.mean_speed = map.required<double>("mean_speed");
      if (!std::isfinite(b.mean_speed)) map.fail("mean_speed", "must be a finite number");
    } else {
      const std::string file = map.required<std::string>("speed_table");
      const std::string path = (std::filesystem::path(case_file).parent_path() / file).string();
      b.speed_table = read_speed_table(path, map, "speed_table");
    }
    b.ramp_time = map.optional_non_negative("ramp_time", 0.0);
  } else {
    if (map.has("pressure")) {
      b.pressure = map.required<double>("pressure");
      if (!std::isfinite(*b.pressure)) map.fail("pressure", "must be a finite number");
    }
  }
  map.finish();
  return b;
}

PeriodicAxis read_periodic(MapReader& map, std::size_t index, int dimension) {
  PeriodicAxis p;
  p.line = map.line();
  p.key = fmt::format("boundaries[{}]", index);
  const std::vector<std::string> axes =
      dimension == 2 ? std::vector<std::string>{"x"} : std::vector<std::string>{"x", "y"};
  const std::string axis = map.required<std::string>("axis");
  if (axis == "z") map.fail("axis", "the vertical (z) is not periodic: gravity runs along it");
  if (std::find(axes.begin(), axes.end(), axis) == axes.end())
    map.fail_choice("axis", "periodic axis", axis, axes);
  p.axis = axis[0] - 'x';
  map.required<std::string>("type");  // "periodic", read by the caller
  map.finish();
  return p;
}

DampingZone read_damping_zone(MapReader& map, std::size_t index, const AxisBox& domain,
                              int dimension) {
  DampingZone z;
  z.line = map.line();
  z.key = fmt::format("damping[{}]", index);
  const std::vector<std::string> axes =
      dimension == 2 ? std::vector<std::string>{"x", "z"} : std::vector<std::string>{"x", "y", "z"};
  const std::string axis = map.required<std::string>("axis");
  if (std::find(axes.begin(), axes.end(), axis) == axes.end())
    map.fail_choice("axis", "axis", axis, axes);
  z.axis = axis[0] - 'x';
  auto inside = [&](const std::string& key) {
    const double c = map.required<double>(key);
    if (!(c >= domain.min[z.axis] && c <= domain.max[z.axis])) {
      map.fail(key, fmt::format("{} lies outside the domain along {} ({} to {})", c, axis,
                                domain.min[z.axis], domain.max[z.axis]));
    }
    return c;
  };
  z.from = inside("from");
  z.to = inside("to");
  if (z.to == z.from) map.fail("to", "must differ from 'from' (the zone has no length)");
  z.strength = map.required_positive("strength");
  map.finish();
  return z;
}

}  // namespace sluice::io
