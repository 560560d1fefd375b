#include "sluice/fluid/mac/surface_mesh.hpp"

#include <array>

namespace sluice {

namespace {

struct Corner {
  Vec3 x;
  Real phi;
};

Vec3 crossing(const Corner& a, const Corner& b) {
  const Real t = a.phi / (a.phi - b.phi);
  return a.x + t * (b.x - a.x);
}

// A triangle (2D: a square) with corners on both sides of the level: its piece of surface.
void cut_square(const std::array<Corner, 4>& c, std::vector<Vec3>& out) {
  // Corners in order around the square: 0 (0,0), 1 (1,0), 3 (1,1), 2 (0,1).
  const std::array<int, 4> ring{0, 1, 3, 2};
  std::vector<Vec3> points;
  for (int k = 0; k < 4; ++k) {
    const Corner& a = c[ring[k]];
    const Corner& b = c[ring[(k + 1) % 4]];
    if ((a.phi < 0) != (b.phi < 0)) points.push_back(crossing(a, b));
  }
  if (points.size() == 2) {
    out.insert(out.end(), points.begin(), points.end());
  } else if (points.size() == 4) {
    // A saddle: the mean of the corners says which pairs of crossings join.
    const Real centre = 0.25 * (c[0].phi + c[1].phi + c[2].phi + c[3].phi);
    const bool joined = (centre < 0) == (c[0].phi < 0);
    const std::array<int, 4> order =
        joined ? std::array<int, 4>{0, 1, 2, 3} : std::array<int, 4>{3, 0, 1, 2};
    for (const int k : order) out.push_back(points[k]);
  }
}

void cut_tetrahedron(const std::array<Corner, 4>& c, std::vector<Vec3>& out) {
  std::array<int, 4> inside{}, outside{};
  int n_in = 0, n_out = 0;
  for (int k = 0; k < 4; ++k) (c[k].phi < 0 ? inside[n_in++] : outside[n_out++]) = k;
  if (n_in == 0 || n_out == 0) return;
  if (n_in == 1 || n_out == 1) {
    const int apex = n_in == 1 ? inside[0] : outside[0];
    const std::array<int, 4>& rest = n_in == 1 ? outside : inside;
    for (int k = 0; k < 3; ++k) out.push_back(crossing(c[apex], c[rest[k]]));
    return;
  }
  const Vec3 p0 = crossing(c[inside[0]], c[outside[0]]);
  const Vec3 p1 = crossing(c[inside[0]], c[outside[1]]);
  const Vec3 p2 = crossing(c[inside[1]], c[outside[1]]);
  const Vec3 p3 = crossing(c[inside[1]], c[outside[0]]);
  out.insert(out.end(), {p0, p1, p2, p0, p2, p3});
}

}  // namespace

template <int D>
std::vector<Vec3> surface_mesh(const MacGrid<D>& grid, const CellField& phi) {
  const Lattice<D> cells = grid.cell_lattice();
  Lattice<D> cubes = cells;  // one per lower corner (across the seam too, on a periodic axis)
  for (int a = 0; a < D; ++a)
    if (a != grid.periodic_axis) cubes.dims[a] = std::max(cells.dims[a] - 1, 0);
  std::vector<Vec3> out;
  constexpr int kCorners = 1 << D;
  for (std::size_t k = 0; k < cubes.size(); ++k) {
    const GridIndex<D> base = cubes.coordinates(k);
    std::array<Corner, kCorners> corner;
    bool negative = false, positive = false;
    for (int m = 0; m < kCorners; ++m) {
      GridIndex<D> c = base;
      for (int a = 0; a < D; ++a) c[a] += (m >> a) & 1;
      corner[m] = {to_3d<D>(cells.position(c)), phi[cells.index(c)]};
      (corner[m].phi < 0 ? negative : positive) = true;
    }
    if (!negative || !positive) continue;
    if constexpr (D == 2) {
      cut_square(corner, out);
    } else {
      // Six tetrahedra sharing the diagonal from corner 0 to corner 7, one per path along the
      // cube's edges from 0 to 7.
      constexpr std::array<std::array<int, 2>, 6> paths{
          {{1, 3}, {1, 5}, {2, 3}, {2, 6}, {4, 5}, {4, 6}}};
      for (const auto& path : paths)
        cut_tetrahedron({corner[0], corner[path[0]], corner[path[1]], corner[7]}, out);
    }
  }
  return out;
}

template std::vector<Vec3> surface_mesh<2>(const MacGrid<2>&, const CellField&);
template std::vector<Vec3> surface_mesh<3>(const MacGrid<3>&, const CellField&);

}  // namespace sluice
