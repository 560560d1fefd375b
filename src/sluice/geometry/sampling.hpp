// Filling shapes with particles on a regular lattice of spacing dx: fluid blocks, and the
// layers of boundary particles behind tank sides, boxes and planes.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "sluice/core/types.hpp"
#include "sluice/geometry/axis_box.hpp"

namespace sluice {

// How many lattice points (or cells) of spacing dx a box of that extent holds: the cells along
// each of the case's axes (2D: x and z), multiplied; a double, to count without overflow the
// sizes a mistyped spacing gives, before anything is allocated.
inline double lattice_points(const Vec3& extent, double dx, int dimension) {
  double n = 1;
  for (int a = 0; a < 3; ++a) {
    if (dimension == 2 && a == 1) continue;
    n *= std::ceil(std::max(extent[a], 0.0) / dx);
  }
  return n;
}

// Lattice points min + (k + 1/2) dx inside the box.
template <int D>
std::vector<Vec<D>> sample_box_volume(const AxisBox& box, Real dx);

// `layers` layers of particles behind the closed sides of a tank (the box is its inside),
// corners included. The walls' faces are the box faces; particles sit dx/2, 3dx/2, ... behind.
template <int D>
std::vector<Vec<D>> sample_tank_walls(const AxisBox& inside,
                                      const std::vector<std::string>& open_sides, Real dx,
                                      int layers);

// A solid box: the lattice points inside it within `layers` spacings of its surface, laid from
// each face so that every face has layers dx/2, 3dx/2, ... behind it.
template <int D>
std::vector<Vec<D>> sample_solid_box(const AxisBox& box, Real dx, int layers);

// `layers` layers behind a plane (normal points into the fluid), clipped to `bounds`.
template <int D>
std::vector<Vec<D>> sample_plane_layers(const Vec3& point, const Vec3& normal,
                                        const AxisBox& bounds, Real dx, int layers);

}  // namespace sluice
