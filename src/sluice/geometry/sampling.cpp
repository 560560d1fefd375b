#include "sluice/geometry/sampling.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace sluice {

namespace {

// Where a lattice coordinate lies relative to a box along one axis.
enum class Band { kBelow, kInside, kAbove };

struct AxisCoordinate {
  Real value;
  Band band;
};

// Coordinates along one axis: `layers` below min, the inside lattice, `layers` above max.
std::vector<AxisCoordinate> axis_coordinates(Real min, Real max, Real dx, int layers) {
  std::vector<AxisCoordinate> out;
  for (int j = layers - 1; j >= 0; --j) out.push_back({min - (j + 0.5) * dx, Band::kBelow});
  const int n = std::max(1, static_cast<int>(std::lround((max - min) / dx)));
  const Real step = (max - min) / n;  // equals dx when the length is a multiple of it
  for (int k = 0; k < n; ++k) out.push_back({min + (k + 0.5) * step, Band::kInside});
  for (int j = 0; j < layers; ++j) out.push_back({max + (j + 0.5) * dx, Band::kAbove});
  return out;
}

// The model's axes in 3D numbering (2D: x and z).
template <int D>
constexpr std::array<int, D> axes3() {
  if constexpr (D == 2) {
    return {0, 2};
  } else {
    return {0, 1, 2};
  }
}

// Visits every point of the Cartesian product of per-axis coordinate lists.
template <int D, class Fn>
void for_each_product(const std::array<std::vector<AxisCoordinate>, D>& axes, Fn&& fn) {
  std::array<std::size_t, D> index{};
  while (true) {
    Vec<D> p;
    std::array<Band, D> bands;
    for (int a = 0; a < D; ++a) {
      p[a] = axes[a][index[a]].value;
      bands[a] = axes[a][index[a]].band;
    }
    fn(p, bands);
    int a = 0;
    while (a < D && ++index[a] == axes[a].size()) index[a++] = 0;
    if (a == D) return;
  }
}

// How many whole particle volumes of size dx fit in [min, max]; the 1e-6 absorbs rounding of
// lengths that are multiples of dx.
long whole_volumes(Real min, Real max, Real dx) {
  return static_cast<long>(std::floor((max - min) / dx + 1e-6));
}

// Coordinates along one axis of a solid box, dx/2, 3dx/2, ... in from each face, the whole
// particle volumes shared between the two faces and the remainder left in the middle (a gap of
// dx to 2dx there). Every face thus has its outer layer half a spacing behind it, as a tank's
// sides do; a lattice laid from one face would leave the other face's layer up to 1.5 dx back.
std::vector<AxisCoordinate> face_aligned_coordinates(Real min, Real max, Real dx) {
  const long n = whole_volumes(min, max, dx);
  if (n == 1) return {{0.5 * (min + max), Band::kInside}};  // one layer: centred, not leaning
  const long from_min = (n + 1) / 2;
  std::vector<AxisCoordinate> out;
  for (long k = 0; k < from_min; ++k) out.push_back({min + (k + 0.5) * dx, Band::kInside});
  for (long k = n - from_min - 1; k >= 0; --k) out.push_back({max - (k + 0.5) * dx, Band::kInside});
  return out;
}

}  // namespace

template <int D>
std::vector<Vec<D>> sample_box_volume(const AxisBox& box, Real dx) {
  std::vector<Vec<D>> out;
  std::array<std::vector<Real>, D> coords;
  constexpr auto axes = axes3<D>();
  for (int a = 0; a < D; ++a) {
    const Real lo = box.min[axes[a]], hi = box.max[axes[a]];
    const long n = whole_volumes(lo, hi, dx);
    for (long k = 0; k < n; ++k) coords[a].push_back(lo + (k + 0.5) * dx);
  }
  std::array<std::vector<AxisCoordinate>, D> lists;
  for (int a = 0; a < D; ++a) {
    for (Real x : coords[a]) lists[a].push_back({x, Band::kInside});
    if (lists[a].empty()) return out;
  }
  for_each_product<D>(lists, [&](const Vec<D>& p, const auto&) { out.push_back(p); });
  return out;
}

template <int D>
std::vector<Vec<D>> sample_tank_walls(const AxisBox& inside,
                                      const std::vector<std::string>& open_sides, Real dx,
                                      int layers) {
  constexpr auto axes = axes3<D>();
  auto is_open = [&](int axis3, bool upper) {
    const std::string side = std::string(1, "xyz"[axis3]) + (upper ? "+" : "-");
    return std::find(open_sides.begin(), open_sides.end(), side) != open_sides.end();
  };
  std::array<std::vector<AxisCoordinate>, D> lists;
  for (int a = 0; a < D; ++a) {
    lists[a] = axis_coordinates(inside.min[axes[a]], inside.max[axes[a]], dx, layers);
  }
  std::vector<Vec<D>> out;
  for_each_product<D>(lists, [&](const Vec<D>& p, const std::array<Band, D>& bands) {
    bool outside = false;
    for (int a = 0; a < D; ++a) {
      if (bands[a] == Band::kInside) continue;
      outside = true;
      if (is_open(axes[a], bands[a] == Band::kAbove)) return;
    }
    if (outside) out.push_back(p);
  });
  return out;
}

template <int D>
std::vector<Vec<D>> sample_solid_box(const AxisBox& box, Real dx, int layers) {
  constexpr auto axes = axes3<D>();
  std::array<std::vector<AxisCoordinate>, D> lists;
  for (int a = 0; a < D; ++a) {
    lists[a] = face_aligned_coordinates(box.min[axes[a]], box.max[axes[a]], dx);
    if (lists[a].empty()) return {};
  }
  std::vector<Vec<D>> out;
  for_each_product<D>(lists, [&](const Vec<D>& p, const auto&) {
    Real depth = 1e300;  // distance to the nearest face
    for (int a = 0; a < D; ++a) {
      depth = std::min({depth, p[a] - box.min[axes[a]], box.max[axes[a]] - p[a]});
    }
    if (depth < layers * dx) out.push_back(p);
  });
  return out;
}

template <int D>
std::vector<Vec<D>> sample_plane_layers(const Vec3& point, const Vec3& normal,
                                        const AxisBox& bounds, Real dx, int layers) {
  AxisBox grown = bounds;
  for (int a = 0; a < 3; ++a) {
    grown.min[a] -= layers * dx;
    grown.max[a] += layers * dx;
  }
  const Vec<D> p0 = from_3d<D>(point);
  const Vec<D> n = from_3d<D>(normal).normalized();
  std::vector<Vec<D>> out;
  for (const Vec<D>& p : sample_box_volume<D>(grown, dx)) {
    const Real s = (p - p0).dot(n);
    if (s < 0 && s > -layers * dx) out.push_back(p);
  }
  return out;
}

#define SLUICE_INSTANTIATE_SAMPLING(D)                                                           \
  template std::vector<Vec<D>> sample_box_volume<D>(const AxisBox&, Real);                       \
  template std::vector<Vec<D>> sample_tank_walls<D>(const AxisBox&,                              \
                                                    const std::vector<std::string>&, Real, int); \
  template std::vector<Vec<D>> sample_solid_box<D>(const AxisBox&, Real, int);                   \
  template std::vector<Vec<D>> sample_plane_layers<D>(const Vec3&, const Vec3&, const AxisBox&,  \
                                                      Real, int);
SLUICE_INSTANTIATE_SAMPLING(2)
SLUICE_INSTANTIATE_SAMPLING(3)
#undef SLUICE_INSTANTIATE_SAMPLING

}  // namespace sluice
