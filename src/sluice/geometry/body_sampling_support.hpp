// What the body samplers share: argument checks, the equal cells along a length, and the
// emitter that appends one layer's particles. Internal to geometry/.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "sluice/geometry/body_sampling.hpp"

namespace sluice::body_sampling {

inline constexpr double kPi = 3.14159265358979323846;
// Most cells along one length; far beyond anything a simulation can hold, it only keeps the
// integer arithmetic below safe.
inline constexpr double kMaxCells = 1e7;

inline void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

inline bool positive_finite(double v) {
  return std::isfinite(v) && v > 0;
}

inline void check_common(const std::string& fn, double dx, int interior_layers, int dimension) {
  require(positive_finite(dx), fn + ": dx must be positive and finite");
  require(interior_layers >= 0, fn + ": interior_layers must be >= 0");
  require(dimension == 2 || dimension == 3, fn + ": dimension must be 2 or 3");
}

inline void check_size(const std::string& fn, const char* what, double value, double dx) {
  require(positive_finite(value), fn + ": " + what + " must be positive and finite");
  require(value / dx < kMaxCells, fn + ": " + what + " is too many spacings dx long");
}

// Equal cells of about dx along a length (at least one).
inline int cell_count(double length, double dx) {
  return std::max(1, static_cast<int>(std::lround(length / dx)));
}

// Appends particles of one layer: surface particles keep their normal and area, interior ones
// get zeros.
class Emitter {
 public:
  Emitter(BodySample& out, int layer) : out_(out), layer_(layer) {}
  void operator()(const Vec3& p, const Vec3& n, double area) const {
    out_.position.push_back(p);
    out_.normal.push_back(layer_ == 0 ? n : Vec3::Zero());
    out_.area.push_back(layer_ == 0 ? area : 0.0);
    out_.layer.push_back(layer_);
  }
  void operator()(const Vec3& p) const { (*this)(p, Vec3::Zero(), 0.0); }
  int layer() const { return layer_; }

 private:
  BodySample& out_;
  int layer_;
};

// Interior layer k of a shape of thickness T would have thickness e = T - 2 k dx. It collapses
// onto the mid-plane (axis, centre) when e < kCollapse dx, and is left out when
// e <= -kCollapse dx (layer k - 1's two sides are then at most 1.5 dx apart). kSlack keeps a
// layer exactly at that limit out despite rounding.
inline constexpr double kCollapse = 0.5;
inline constexpr double kSlack = 1e-9;
}  // namespace sluice::body_sampling
