// What a solid particle's own solid gives its kernel sum where that solid is a flat wall on the
// lattice: the reference against which a body sampled closer than the lattice is normalised (a
// cylinder's rim, where the side's ring and the caps' outer ring lie less than a spacing apart;
// a box's edges, whose two faces' particles lie dx/sqrt(2) apart; a thin part's middle layer).
// Bodies are rigid, so a body particle's sum over its own body is fixed at the start.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "sluice/core/types.hpp"
#include "sluice/coupling/body_geometry.hpp"
#include "sluice/coupling/body_points.hpp"

namespace sluice {

// The sum of w(r) over the points of a lattice of spacing dx within `reach` of one of them that
// lie in a flat wall of `layers` layers, the point being in layer `layer` (0: the layer nearest
// the fluid): the wall's layers are those at offsets -layer .. layers - 1 - layer along x.
template <int D, class Weight>
Real flat_wall_sum(const Weight& w, Real reach, Real dx, int layers, int layer) {
  const int n = static_cast<int>(std::ceil(reach / dx));
  Real sum = 0;
  for (int a = -layer; a <= layers - 1 - layer; ++a) {
    for (int b = -n; b <= n; ++b) {
      for (int c = (D == 3 ? -n : 0); c <= (D == 3 ? n : 0); ++c) {
        const Real r = dx * std::sqrt(Real(a * a + b * b + c * c));
        if (r < reach) sum += w(r);
      }
    }
  }
  return sum;
}

// Each body point's layer under its body's surface, from its depth: layer k lies (k + 1/2) dx
// deep; the deepest points count as the last of `layers`.
inline std::vector<int> body_point_layers(const BodyGeometry& bodies, const BodyPoints& points,
                                          Real dx, int layers) {
  const std::vector<BodyKinematics> motion = bodies.motion();
  std::vector<int> layer(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Real depth = -bodies.nearest_on_body(points[k].body, points.position(k, motion)).distance;
    layer[k] = std::clamp(static_cast<int>(std::lround(depth / dx - 0.5)), 0, layers - 1);
  }
  return layer;
}

}  // namespace sluice
