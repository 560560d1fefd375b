// Open boundaries as read from a case file (docs/case-format.md, "Open boundaries"): a side of
// the domain through which water enters at a prescribed velocity (an inlet) or leaves against a
// prescribed pressure (an outlet). Plain data in SI units.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sluice::io {

enum class BoundaryKind { kInlet, kOutlet };
enum class InletProfile { kUniform, kParabolic };

struct BoundaryConfig {
  std::string name;
  BoundaryKind kind = BoundaryKind::kInlet;
  int axis = 0;        // the side's normal: 0 x, 1 y, 2 z
  bool upper = false;  // the side at the domain's max along `axis`
  // Inlet: the mean speed into the domain over the side's span [m/s], or (a table) its value
  // by time, interpolated linearly and held at the ends; spread uniformly across the span or
  // as a parabola that vanishes at its edges (in 3D the product of one per axis across).
  InletProfile profile = InletProfile::kUniform;
  double mean_speed = 0;
  std::vector<std::pair<double, double>> speed_table;  // (time, mean speed)
  // The inflow starts from rest over ramp_time (0: at once), as a body does (smooth_ramp.hpp).
  double ramp_time = 0;
  // The water's surface height at the side (a free-surface channel): water enters below it,
  // and an outlet's pressure is hydrostatic below it. Unset: the side's whole span.
  std::optional<double> depth;
  // Outlet: the pressure at the side (above `depth`) [Pa]. Unset: the grid model takes 0; a
  // particle model prescribes none where `depth` is unset too (the fluid's own pressure).
  std::optional<double> pressure;
  std::string key;  // "boundaries[N]", for messages
  int line = 0;

  // The inlet's mean speed at `time`, ramped.
  double speed_at(double time) const;
  // The inflow's profile at share `s` (0 to 1) of the span along one axis across the side, of
  // mean 1: 1, or the parabola 6 s (1 - s).
  double profile_across(double s) const {
    if (profile == InletProfile::kUniform) return 1;
    return s > 0 && s < 1 ? 6 * s * (1 - s) : 0;
  }
  // "x-", "z+", ...
  std::string side_name() const { return std::string(1, "xyz"[axis]) + (upper ? "+" : "-"); }
};

// A periodic pair of sides (`type: periodic`): water that leaves the domain through one side
// along `axis` enters it through the other, and each side's water sees the other's as its
// neighbours.
struct PeriodicAxis {
  int axis = 0;     // 0 x, 1 y (never the vertical)
  std::string key;  // "boundaries[N]", for messages
  int line = 0;
};

// A damping zone (a "sponge layer"): the water's velocity relaxed towards rest, at a rate that
// grows from 0 at `from` to `strength` at `to` along `axis` as the square of the distance's
// share, and stays at `strength` beyond `to` (`to` < `from`: a zone towards the axis's lower
// end). Over a step dt the velocity is multiplied by exp(-rate dt).
struct DampingZone {
  int axis = 0;             // 0 x, 1 y, 2 z
  double from = 0, to = 0;  // [m]
  double strength = 0;      // [1/s]
  std::string key;          // "damping[N]", for messages
  int line = 0;

  // The relaxation rate [1/s] at coordinate `c` along the axis.
  double rate_at(double c) const {
    const double s = (c - from) / (to - from);
    if (s <= 0) return 0;
    return s >= 1 ? strength : strength * s * s;
  }
};

}  // namespace sluice::io
