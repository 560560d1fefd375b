// An axis-aligned box: a case's domain, a tank, a body's bounding box in contact.
#pragma once

#include <limits>

#include "sluice/core/types.hpp"

namespace sluice {

struct AxisBox {
  Vec3 min = Vec3::Zero();
  Vec3 max = Vec3::Zero();

  // A box that holds nothing, to grow point by point.
  static AxisBox empty() {
    const double inf = std::numeric_limits<double>::infinity();
    return {Vec3::Constant(inf), Vec3::Constant(-inf)};
  }
  void grow(const Vec3& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  // Whether p lies inside; a 2D case (x-z plane) ignores y.
  bool contains(const Vec3& p, int dimension) const {
    for (int a = 0; a < 3; ++a) {
      if (dimension == 2 && a == 1) continue;
      if (p[a] < min[a] || p[a] > max[a]) return false;
    }
    return true;
  }
  // Whether p lies inside the box grown by `margin` on every side.
  bool contains_within(const Vec3& p, double margin) const {
    return (p.array() >= min.array() - margin).all() && (p.array() <= max.array() + margin).all();
  }
  bool overlaps(const AxisBox& o, double margin) const {
    return (min.array() - margin <= o.max.array()).all() &&
           (o.min.array() - margin <= max.array()).all();
  }
};

}  // namespace sluice
