#include "sluice/fluid/mac/solid_boundary.hpp"

#include <algorithm>

#include "sluice/exec/policy.hpp"

namespace sluice {

namespace {

// The fraction of a face (2D: a segment between two corners; 3D: a square of four) outside
// the solid, from the signed distance at its corners: exact for a segment, and for a square
// the mean of 4 x 4 sub-squares' smoothed fractions under bilinear interpolation.
template <int D>
Real open_fraction(const std::array<Real, (1 << (D - 1))>& corner) {
  if constexpr (D == 2) {
    return positive_fraction(corner[0], corner[1]);
  } else {
    if (std::min({corner[0], corner[1], corner[2], corner[3]}) >= 0) return 1;
    if (std::max({corner[0], corner[1], corner[2], corner[3]}) < 0) return 0;
    constexpr int kSamples = 4;
    Real open = 0;
    for (int i = 0; i < kSamples; ++i) {
      for (int j = 0; j < kSamples; ++j) {
        const Real s = (i + 0.5) / kSamples, t = (j + 0.5) / kSamples;
        const Real lower = (1 - s) * corner[0] + s * corner[1];
        const Real upper = (1 - s) * corner[2] + s * corner[3];
        open += ((1 - t) * lower + t * upper) >= 0 ? 1 : 0;
      }
    }
    return open / (kSamples * kSamples);
  }
}

// The fraction of a face's control volume (from one cell centre to the next along the face's
// axis a, the face's extent across) outside the solid: the mean, over 4 (3D: 4 x 4) lines
// along a through it, of each line's part outside, from the distance at its two ends. Batty,
// Bertails & Bridson (2007) weight each face by this fraction. A solid's face lying across a
// cell then loads the pressure in proportion to where it lies; the face-area fraction alone
// sees it at the next cell face, and a held box's underside anywhere in a cell took the load
// of the cell's centre (25 % short of the hydrostatic at 4 cells of depth).
template <int D>
Real control_volume_open_fraction(const Lattice<D>& nodes, const std::vector<Real>& distance,
                                  const Vec<D>& face_centre, int axis, Real h) {
  constexpr int kLines = 4;
  constexpr int kAcross = D - 1;
  int total = 1;
  for (int k = 0; k < kAcross; ++k) total *= kLines;
  Real open = 0;
  for (int line = 0; line < total; ++line) {
    Vec<D> x = face_centre;
    int code = line;
    for (int b = 0; b < D; ++b) {
      if (b == axis) continue;
      x[b] += ((code % kLines) + 0.5) / kLines * h - 0.5 * h;
      code /= kLines;
    }
    Vec<D> lower = x, upper = x;
    lower[axis] -= 0.5 * h;
    upper[axis] += 0.5 * h;
    open += positive_fraction(nodes.sample(distance, lower), nodes.sample(distance, upper));
  }
  return open / total;
}

// The least open fraction a face beside a moving body keeps; below it the face is closed. A
// moving body's swept volume leaves a cell through its open faces, at the body's speed over
// their open fraction: in the wedge of water between a rolling wheel and the bed a face open by
// 1e-4 carried thousands of metres a second and the run collapsed (docs/validation.md, B5).
// Closed below 5 %, a face takes at most 20 times the body's speed. Walls and bodies at rest
// sweep nothing and keep every fraction.
constexpr Real kSmallestOpenBesideAMovingBody = 0.05;

}  // namespace

template <int D>
SolidBoundary<D>::SolidBoundary(const MacGrid<D>& grid, const BodyGeometry& geometry,
                                OpenBoundaries<D> open)
    : grid_(grid), geometry_(&geometry), open_(std::move(open)) {
  const Lattice<D> nodes = grid.node_lattice();
  wall_nodes_.resize(nodes.size());
  exec::Default::for_each(nodes.size(), [&](std::size_t k) {
    wall_nodes_[k] =
        geometry.nearest_on_walls(to_3d<D>(nodes.position(nodes.coordinates(k)))).distance;
  });
  const std::vector<BodyPoint> surface = geometry.surface_points();
  body_reach_.assign(geometry.body_count(), 0);
  for (const BodyPoint& p : surface)
    body_reach_[p.body] = std::max(body_reach_[p.body], p.local.norm());
  place_bodies(geometry.motion());
}

template <int D>
void SolidBoundary<D>::place_bodies(const std::vector<BodyKinematics>& motion) {
  const Lattice<D> nodes = grid_.node_lattice();
  nodes_ = wall_nodes_;
  nearest_body_.assign(nodes.size(), -1);
  // Each body's distance on the nodes within its reach (plus two cells): farther nodes are
  // outside it by more than any face needs.
  for (std::size_t b = 0; b < motion.size(); ++b) {
    const Vec<D> centre = from_3d<D>(motion[b].position);
    const Real reach = body_reach_[b] + 2 * grid_.h;
    GridIndex<D> lo, hi;
    for (int a = 0; a < D; ++a) {
      lo[a] = std::max(
          0, static_cast<int>(std::floor((centre[a] - reach - grid_.origin[a]) / grid_.h)));
      hi[a] =
          std::min(nodes.dims[a] - 1,
                   static_cast<int>(std::ceil((centre[a] + reach - grid_.origin[a]) / grid_.h)));
      if (hi[a] < lo[a]) hi[a] = lo[a] - 1;
    }
    Lattice<D> box;
    std::size_t count = 1;
    for (int a = 0; a < D; ++a) {
      box.dims[a] = std::max(0, hi[a] - lo[a] + 1);
      count *= static_cast<std::size_t>(box.dims[a]);
    }
    exec::Default::for_each(count, [&](std::size_t j) {
      GridIndex<D> c = box.coordinates(j);
      for (int a = 0; a < D; ++a) c[a] += lo[a];
      const std::size_t k = nodes.index(c);
      const Real d = geometry_->nearest_on_body(b, to_3d<D>(nodes.position(c))).distance;
      if (d < nodes_[k]) {
        nodes_[k] = d;
        nearest_body_[k] = static_cast<int>(b);
      }
    });
  }
  fill_faces(motion);
}

template <int D>
void SolidBoundary<D>::at_time(double time) {
  time_ = time;
  if (!open_.empty()) open_.apply(faces_, time_);
}

template <int D>
Vec<D> SolidBoundary<D>::wall_velocity_at(const Vec<D>& x) const {
  return from_3d<D>(geometry_->nearest_on_walls(to_3d<D>(x)).velocity);
}

template <int D>
void SolidBoundary<D>::fill_faces(const std::vector<BodyKinematics>& motion) {
  const Lattice<D> nodes = grid_.node_lattice();
  const Lattice<D> cells = grid_.cell_lattice();
  for (int a = 0; a < D; ++a) {
    const Lattice<D> faces = grid_.face_lattice(a);
    faces_.open[a].assign(faces.size(), 1);
    faces_.velocity[a].assign(faces.size(), 0);
    faces_.body[a].assign(faces.size(), -1);
    exec::Default::for_each(faces.size(), [&](std::size_t f) {
      const GridIndex<D> c = faces.coordinates(f);
      const Vec<D> centre = faces.position(c);
      // The corners of the face: its node (the lowest) and those one step along the other axes.
      std::array<Real, (1 << (D - 1))> corner;
      std::array<std::size_t, (1 << (D - 1))> corner_node;
      for (int k = 0; k < (1 << (D - 1)); ++k) {
        GridIndex<D> n = c;
        int bit = 0;
        for (int b = 0; b < D; ++b) {
          if (b == a) continue;
          if ((k >> bit++) & 1) n[b] += 1;
        }
        corner_node[k] = nodes.index(n);
        corner[k] = nodes_[corner_node[k]];
      }
      // The control volume lies within 1.5 h of the corners: beyond that from every solid it
      // is open, that deep inside one closed. On the grid's boundary it has no far side.
      const Real nearest = *std::min_element(corner.begin(), corner.end());
      const Real farthest = *std::max_element(corner.begin(), corner.end());
      const bool on_boundary = grid_.on_boundary(a, c[a]);
      Real open = nearest >= 1.5 * grid_.h    ? Real(1)
                  : farthest < -1.5 * grid_.h ? Real(0)
                  : on_boundary
                      ? open_fraction<D>(corner)
                      : control_volume_open_fraction<D>(nodes, nodes_, centre, a, grid_.h);
      int body = -1;
      Vec<D> velocity = Vec<D>::Zero();
      if (on_boundary) {
        // On the grid's boundary: closed where a wall lies beyond, open to air elsewhere.
        Vec<D> beyond = centre;
        beyond[a] += (c[a] == 0 ? -0.5 : 0.5) * grid_.h;
        const SurfacePoint wall = geometry_->nearest_on_walls(to_3d<D>(beyond));
        open = std::min(open, wall.distance < 0 ? Real(0) : Real(1));
        velocity = from_3d<D>(wall.velocity);
      } else if (open < 1) {
        for (const std::size_t n : corner_node)
          if (nearest_body_[n] >= 0) body = nearest_body_[n];
        if (body < 0) velocity = wall_velocity_at(centre);
      }
      if (body >= 0) {
        const BodyKinematics& m = motion[static_cast<std::size_t>(body)];
        const bool moving = !m.velocity.isZero(0) || !m.angular_velocity.isZero(0);
        if (moving && open < kSmallestOpenBesideAMovingBody) open = 0;
        const Vec3 r = to_3d<D>(centre) - m.position;
        velocity = from_3d<D>(m.velocity + m.angular_velocity.cross(r));
      }
      faces_.open[a][f] = open;
      faces_.velocity[a][f] = velocity[a];
      faces_.body[a][f] = body;
    });
  }
  if (!open_.empty()) open_.apply(faces_, time_);
  solid_cell_.assign(cells.size(), 0);
  const Lattice<D> node_lattice = nodes;
  exec::Default::for_each_light(cells.size(), [&](std::size_t k) {
    solid_cell_[k] = node_lattice.sample(nodes_, cells.position(cells.coordinates(k))) < 0;
  });
}

template class SolidBoundary<2>;
template class SolidBoundary<3>;

}  // namespace sluice
