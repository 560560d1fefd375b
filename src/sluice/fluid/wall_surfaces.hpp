// The walls as a fluid particle meets them in the neighbour stage, in plain arrays that a device
// run reads as the host does (RigidBodies::nearest_on_walls's geometry): each closed side of a
// tank and each plane wall is a plane with its solid behind it, each box wall a box with its
// solid inside. A fluid particle found in a wall's solid, within the walls' particle layers, is
// put back on the nearest surface of the wall it is deepest in, and loses its velocity into it.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "sluice/core/host_device.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/io/wall_pieces.hpp"

namespace sluice {

struct WallSurfacesView {
  const double* plane = nullptr;  // 6 reals each: a point, the unit normal into the fluid
  std::uint32_t planes = 0;
  const double* box = nullptr;  // 6 reals each: the centre, the half sizes
  std::uint32_t boxes = 0;
  double band = 0;  // the walls' particle layers' thickness: deeper in, a particle is left be
  int dimension = 3;
};

// Whether the point p (3 reals; 2D: y ignored) lies in a wall's solid.
SLUICE_HOST_DEVICE inline bool in_wall_solid(const WallSurfacesView& w, const double* p) {
  for (std::uint32_t k = 0; k < w.planes; ++k) {
    const double* q = w.plane + 6 * k;
    if ((p[0] - q[0]) * q[3] + (p[1] - q[1]) * q[4] + (p[2] - q[2]) * q[5] < 0) return true;
  }
  for (std::uint32_t k = 0; k < w.boxes; ++k) {
    const double* b = w.box + 6 * k;
    bool inside = true;
    for (int a = 0; a < 3; ++a) {
      if (w.dimension == 2 && a == 1) continue;
      inside = inside && p[a] > b[a] - b[3 + a] && p[a] < b[a] + b[3 + a];
    }
    if (inside) return true;
  }
  return false;
}

// Takes away the part of v (D reals) along -n, into the wall.
template <int D>
SLUICE_HOST_DEVICE inline void stop_into_wall(const double* n, double* v) {
  double inward = 0;
  for (int a = 0; a < D; ++a) inward += v[a] * n[a];
  if (inward < 0) {
    for (int a = 0; a < D; ++a) v[a] -= inward * n[a];
  }
}

// Puts a fluid particle at x moving at v (D reals each) back on the wall's surface, as above.
// `carried`, when given, is the velocity the rest of the model's step builds on (the half-step
// velocity of a kick-drift-kick step, which the second kick turns into v): it loses its part
// into the wall too, or the second kick would give the particle back its speed into the wall,
// and a particle held on the wall by suction would gather speed step after step.
template <int D>
SLUICE_HOST_DEVICE SLUICE_ONE_HOST_COPY inline void keep_out_of_wall_solids(
    const WallSurfacesView& w, double* x, double* v, double* carried = nullptr) {
  const double p[3] = {x[0], D == 3 ? x[1] : 0.0, x[D - 1]};
  if (!in_wall_solid(w, p)) return;
  double best = std::numeric_limits<double>::infinity();
  double closest[3] = {p[0], p[1], p[2]}, normal[3] = {0, 0, 0};
  for (std::uint32_t k = 0; k < w.planes; ++k) {
    const double* q = w.plane + 6 * k;
    const double d = (p[0] - q[0]) * q[3] + (p[1] - q[1]) * q[4] + (p[2] - q[2]) * q[5];
    if (!(d < best)) continue;
    best = d;
    for (int a = 0; a < 3; ++a) {
      normal[a] = q[3 + a];
      closest[a] = p[a] - d * q[3 + a];
    }
  }
  for (std::uint32_t k = 0; k < w.boxes; ++k) {
    const double* b = w.box + 6 * k;
    double r[3];
    int axis = -1;
    double depth = -std::numeric_limits<double>::infinity();  // the nearest face's, <= 0 inside
    bool inside = true;
    for (int a = 0; a < 3; ++a) {
      r[a] = p[a] - b[a];
      if (w.dimension == 2 && a == 1) continue;
      const double q = (r[a] < 0 ? -r[a] : r[a]) - b[3 + a];
      inside = inside && q <= 0;
      if (q > depth) {
        depth = q;
        axis = a;
      }
    }
    if (!inside || !(depth < best)) continue;
    best = depth;
    for (int a = 0; a < 3; ++a) {
      normal[a] = a == axis ? (r[a] < 0 ? -1.0 : 1.0) : 0.0;
      closest[a] = (a == axis ? normal[a] * b[3 + a] : r[a]) + b[a];
    }
  }
  if (!(best < 0) || best < -w.band) return;
  double n[D];
  for (int a = 0; a < D; ++a) {
    const int a3 = D == 3 ? a : 2 * a;
    n[a] = normal[a3];
    x[a] = closest[a3];
  }
  stop_into_wall<D>(n, v);
  if (carried) stop_into_wall<D>(n, carried);
}

// The arrays behind a view, from the case's walls.
class WallSurfaces {
 public:
  WallSurfaces(const std::vector<io::WallConfig>& walls, int dimension, double band)
      : dimension_(dimension), band_(band) {
    for_each_wall_piece(
        walls, dimension,
        [&](const io::WallConfig&, const Vec3& point, const Vec3& normal) {
          add(plane_, point, normal);
        },
        [&](const io::WallConfig&, const Vec3& centre, const Vec3& half) {
          add(box_, centre, half);
        });
  }

  WallSurfacesView view() const {
    return {plane_.data(), static_cast<std::uint32_t>(plane_.size() / 6),
            box_.data(),   static_cast<std::uint32_t>(box_.size() / 6),
            band_,         dimension_};
  }
  const std::vector<double>& planes() const { return plane_; }
  const std::vector<double>& boxes() const { return box_; }
  bool contains(const Vec3& x) const { return in_wall_solid(view(), x.data()); }

 private:
  static void add(std::vector<double>& to, const Vec3& first, const Vec3& second) {
    to.insert(to.end(), first.data(), first.data() + 3);
    to.insert(to.end(), second.data(), second.data() + 3);
  }
  int dimension_;
  double band_;
  std::vector<double> plane_, box_;
};

}  // namespace sluice
