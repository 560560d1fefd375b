// Surface and interior particles of closed triangle meshes.
#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "sluice/geometry/body_sampling.hpp"
#include "sluice/geometry/body_sampling_support.hpp"

namespace sluice {

using namespace body_sampling;

namespace {

// ---------------------------------------------------------------------------------------------
// Triangle meshes

using Vec2 = Eigen::Vector2d;
using Polygon = std::vector<Vec2>;

double cross2(const Vec2& a, const Vec2& b) {
  return a[0] * b[1] - a[1] * b[0];
}

Vec3 closest_on_segment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 == 0) return a;
  return a + std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) * ab;
}

// The point of triangle abc nearest to p: the projection onto its plane when that falls inside,
// else the nearest point of its three edges.
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const double n2 = n.squaredNorm();
  if (n2 > 0) {
    const Vec3 q = p - n * (n.dot(p - a) / n2);
    if ((b - a).cross(q - a).dot(n) >= 0 && (c - b).cross(q - b).dot(n) >= 0 &&
        (a - c).cross(q - c).dot(n) >= 0) {
      return q;
    }
  }
  Vec3 best = closest_on_segment(p, a, b);
  for (const Vec3& cand : {closest_on_segment(p, b, c), closest_on_segment(p, c, a)}) {
    if ((cand - p).squaredNorm() < (best - p).squaredNorm()) best = cand;
  }
  return best;
}

// Solid angle of triangle abc seen from p (positive when p is behind its counter-clockwise
// side), by the half-angle tangent formula of Van Oosterom and Strackee.
double solid_angle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ra = a - p, rb = b - p, rc = c - p;
  const double la = ra.norm(), lb = rb.norm(), lc = rc.norm();
  const double num = ra.dot(rb.cross(rc));
  const double den = la * lb * lc + ra.dot(rb) * lc + ra.dot(rc) * lb + rb.dot(rc) * la;
  return 2 * std::atan2(num, den);
}

// Keeps the part of a convex polygon on one side of the line x[axis] = bound.
Polygon clip(const Polygon& in, int axis, double bound, bool keep_above) {
  Polygon out;
  if (std::isinf(bound)) return in;
  auto inside = [&](const Vec2& q) { return keep_above ? q[axis] >= bound : q[axis] <= bound; };
  for (std::size_t i = 0; i < in.size(); ++i) {
    const Vec2& p = in[i];
    const Vec2& q = in[(i + 1) % in.size()];
    const bool p_in = inside(p), q_in = inside(q);
    if (p_in) out.push_back(p);
    if (p_in != q_in) {
      Vec2 x = p + (bound - p[axis]) / (q[axis] - p[axis]) * (q - p);
      x[axis] = bound;
      out.push_back(x);
    }
  }
  return out;
}

// Area and centroid of a simple polygon (counter-clockwise: positive area).
std::pair<double, Vec2> area_centroid(const Polygon& poly) {
  if (poly.size() < 3) return {0.0, Vec2::Zero()};
  const Vec2 o = poly[0];
  double twice_area = 0;
  Vec2 moment = Vec2::Zero();
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
    const Vec2 a = poly[i] - o, b = poly[i + 1] - o;
    const double t = cross2(a, b);
    twice_area += t;
    moment += t * (a + b) / 3;
  }
  if (twice_area <= 0) return {0.0, Vec2::Zero()};
  return {0.5 * twice_area, o + moment / twice_area};
}

struct MeshTriangle {
  std::array<int, 3> v;  // welded vertex indices
  Vec3 a, b, c;          // corners
  Vec3 normal;
  double area;
};

struct Piece {                      // one cell of a face grid clipped to the face
  double area = 0;                  // true (not projected) area
  Vec2 moment = Vec2::Zero();       // area times centroid, face coordinates
  Vec3 area_normal = Vec3::Zero();  // sum of area times triangle normal
  std::vector<int> triangles;       // triangles (mesh indices) that contributed
  std::vector<std::array<int, 2>> cells;
  int merged_into = -1;
};

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Surface particles of one planar face made of `ids` (indices into tris).
void sample_face(const std::vector<MeshTriangle>& tris, const std::vector<int>& ids,
                 const std::vector<Vec3>& welded, double dx, const Emitter& emit) {
  Vec3 normal_sum = Vec3::Zero();
  for (int t : ids) normal_sum += tris[t].area * tris[t].normal;
  const Vec3 nf = normal_sum.normalized();

  // Frame: u along the longest boundary edge (an edge used once within the face).
  std::map<std::pair<int, int>, int> edge_use;
  for (int t : ids) {
    for (int k = 0; k < 3; ++k) {
      const int i = tris[t].v[k], j = tris[t].v[(k + 1) % 3];
      ++edge_use[{std::min(i, j), std::max(i, j)}];
    }
  }
  int from = tris[ids[0]].v[0], to = tris[ids[0]].v[1];
  double longest = -1;
  for (int t : ids) {
    for (int k = 0; k < 3; ++k) {
      const int i = tris[t].v[k], j = tris[t].v[(k + 1) % 3];
      if (edge_use[{std::min(i, j), std::max(i, j)}] != 1) continue;
      const double len = (welded[j] - welded[i]).norm();
      if (len > longest) {
        longest = len;
        from = i;
        to = j;
      }
    }
  }
  const Vec3 origin = welded[from];
  Vec3 u = welded[to] - origin;
  u -= nf * nf.dot(u);
  if (u.norm() == 0) u = nf.unitOrthogonal();
  u.normalize();
  const Vec3 v = nf.cross(u);
  auto to2 = [&](const Vec3& x) { return Vec2((x - origin).dot(u), (x - origin).dot(v)); };

  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (int t : ids) {
    for (const Vec3* x : {&tris[t].a, &tris[t].b, &tris[t].c}) {
      lo = lo.cwiseMin(to2(*x));
      hi = hi.cwiseMax(to2(*x));
    }
  }
  std::array<int, 2> count;
  std::array<double, 2> step;
  for (int a = 0; a < 2; ++a) {
    count[a] = cell_count(hi[a] - lo[a], dx);
    step[a] = (hi[a] - lo[a]) / count[a];
    if (!(step[a] > 0)) step[a] = 1;
  }
  const double inf = std::numeric_limits<double>::infinity();
  // Cell bounds; the outer cells reach to infinity so rounding can lose nothing.
  auto bound = [&](int a, int i) {
    if (i <= 0) return -inf;
    if (i >= count[a]) return inf;
    return lo[a] + i * step[a];
  };
  auto cell_of = [&](int a, double x) {
    return std::clamp(static_cast<int>(std::floor((x - lo[a]) / step[a])), 0, count[a] - 1);
  };

  std::vector<Piece> pieces;
  std::map<std::array<int, 2>, int> piece_at;  // cell -> index into pieces
  for (int t : ids) {
    const Polygon tri = {to2(tris[t].a), to2(tris[t].b), to2(tris[t].c)};
    const double projected = 0.5 * cross2(tri[1] - tri[0], tri[2] - tri[0]);
    if (!(projected > 0)) continue;
    const double scale = tris[t].area / projected;  // 1 up to the face's flatness tolerance
    Vec2 tlo = tri[0].cwiseMin(tri[1]).cwiseMin(tri[2]);
    Vec2 thi = tri[0].cwiseMax(tri[1]).cwiseMax(tri[2]);
    // One cell more each way: a corner on a cell boundary may round into either cell.
    const int j0 = std::max(0, cell_of(1, tlo[1]) - 1),
              j1 = std::min(count[1] - 1, cell_of(1, thi[1]) + 1);
    const int i0 = std::max(0, cell_of(0, tlo[0]) - 1),
              i1 = std::min(count[0] - 1, cell_of(0, thi[0]) + 1);
    for (int j = j0; j <= j1; ++j) {
      const Polygon row = clip(clip(tri, 1, bound(1, j), true), 1, bound(1, j + 1), false);
      if (row.size() < 3) continue;
      for (int i = i0; i <= i1; ++i) {
        const Polygon cell = clip(clip(row, 0, bound(0, i), true), 0, bound(0, i + 1), false);
        const auto [area2, centroid] = area_centroid(cell);
        if (!(area2 > 0)) continue;
        const double area = area2 * scale;
        auto [it, fresh] = piece_at.try_emplace({i, j}, static_cast<int>(pieces.size()));
        if (fresh) {
          pieces.emplace_back();
          pieces.back().cells.push_back({i, j});
        }
        Piece& piece = pieces[it->second];
        piece.area += area;
        piece.moment += area * centroid;
        piece.area_normal += area * tris[t].normal;
        if (std::find(piece.triangles.begin(), piece.triangles.end(), t) == piece.triangles.end()) {
          piece.triangles.push_back(t);
        }
      }
    }
  }

  // Merge pieces under a quarter cell, smallest first, into their largest neighbour.
  const double small = 0.25 * (hi[0] - lo[0]) / count[0] * (hi[1] - lo[1]) / count[1];
  auto root = [&](int p) {
    while (pieces[p].merged_into >= 0) p = pieces[p].merged_into;
    return p;
  };
  std::vector<int> order(pieces.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return pieces[a].area < pieces[b].area; });
  for (int p : order) {
    if (pieces[p].merged_into >= 0 || pieces[p].area >= small) continue;
    int target = -1;
    for (const auto& cell : pieces[p].cells) {
      for (int dj = -1; dj <= 1; ++dj) {
        for (int di = -1; di <= 1; ++di) {
          const auto it = piece_at.find({cell[0] + di, cell[1] + dj});
          if (it == piece_at.end()) continue;
          const int q = root(it->second);
          if (q == p) continue;
          if (target < 0 || pieces[q].area > pieces[target].area ||
              (pieces[q].area == pieces[target].area && q < target)) {
            target = q;
          }
        }
      }
    }
    if (target < 0) continue;
    Piece& into = pieces[target];
    into.area += pieces[p].area;
    into.moment += pieces[p].moment;
    into.area_normal += pieces[p].area_normal;
    for (int t : pieces[p].triangles) {
      if (std::find(into.triangles.begin(), into.triangles.end(), t) == into.triangles.end()) {
        into.triangles.push_back(t);
      }
    }
    into.cells.insert(into.cells.end(), pieces[p].cells.begin(), pieces[p].cells.end());
    pieces[p].merged_into = target;
  }

  for (const Piece& piece : pieces) {
    if (piece.merged_into >= 0) continue;
    const Vec2 c = piece.moment / piece.area;
    const Vec3 guess = origin + c[0] * u + c[1] * v;
    // Onto the surface: the nearest point of the piece's own triangles (the centroid itself,
    // unless the face is slightly bent or a merged piece's centroid left a non-convex face).
    Vec3 best = guess;
    double best_d2 = inf;
    for (int t : piece.triangles) {
      const Vec3 q = closest_on_triangle(guess, tris[t].a, tris[t].b, tris[t].c);
      const double d2 = (q - guess).squaredNorm();
      if (d2 < best_d2) {
        best_d2 = d2;
        best = q;
      }
    }
    emit(best, piece.area_normal.normalized(), piece.area);
  }
}

}  // namespace

BodySample sample_mesh_body(const TriangleMesh& mesh, double dx, int interior_layers) {
  const std::string fn = "sample_mesh_body";
  check_common(fn, dx, interior_layers, 3);

  // Weld vertices at the same position, so faces join across duplicated vertices.
  std::map<std::array<double, 3>, int> weld;
  std::vector<int> welded_of(mesh.vertices.size());
  std::vector<Vec3> welded;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& x = mesh.vertices[i];
    require(x.allFinite(), fn + ": vertex coordinates must be finite");
    const auto [it, fresh] = weld.try_emplace({x[0], x[1], x[2]}, static_cast<int>(welded.size()));
    if (fresh) welded.push_back(x);
    welded_of[i] = it->second;
  }
  Vec3 box_lo = Vec3::Constant(std::numeric_limits<double>::infinity()), box_hi = -box_lo;
  for (const Vec3& x : welded) {
    box_lo = box_lo.cwiseMin(x);
    box_hi = box_hi.cwiseMax(x);
  }
  const double diagonal = welded.empty() ? 0.0 : (box_hi - box_lo).norm();

  std::vector<MeshTriangle> tris;
  for (const auto& t : mesh.triangles) {
    for (std::uint32_t i : t) require(i < mesh.vertices.size(), fn + ": vertex index out of range");
    MeshTriangle m;
    for (int k = 0; k < 3; ++k) m.v[k] = welded_of[t[k]];
    m.a = welded[m.v[0]];
    m.b = welded[m.v[1]];
    m.c = welded[m.v[2]];
    const Vec3 cross = (m.b - m.a).cross(m.c - m.a);
    m.area = 0.5 * cross.norm();
    if (!(m.area > 1e-15 * diagonal * diagonal)) continue;  // degenerate: nothing to sample
    m.normal = cross.normalized();
    tris.push_back(m);
  }
  require(!tris.empty(), fn + ": the mesh has no triangle of nonzero area");
  for (int a = 0; a < 3; ++a) {
    require((box_hi[a] - box_lo[a]) / dx < kMaxCells, fn + ": the mesh is too many dx across");
  }

  // Faces: edge-adjacent triangles whose normals agree (to about 1e-6 rad).
  std::vector<int> parent(tris.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::map<std::pair<int, int>, std::vector<int>> edge_tris;
  for (std::size_t t = 0; t < tris.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int i = tris[t].v[k], j = tris[t].v[(k + 1) % 3];
      edge_tris[{std::min(i, j), std::max(i, j)}].push_back(static_cast<int>(t));
    }
  }
  for (const auto& [edge, list] : edge_tris) {
    for (std::size_t x = 0; x < list.size(); ++x) {
      for (std::size_t y = x + 1; y < list.size(); ++y) {
        if (tris[list[x]].normal.dot(tris[list[y]].normal) > 1 - 5e-13) {
          parent[find_root(parent, list[x])] = find_root(parent, list[y]);
        }
      }
    }
  }
  std::map<int, std::vector<int>> faces_by_root;
  std::vector<int> face_order;  // roots by first triangle
  for (std::size_t t = 0; t < tris.size(); ++t) {
    const int r = find_root(parent, static_cast<int>(t));
    auto& list = faces_by_root[r];
    if (list.empty()) face_order.push_back(r);
    list.push_back(static_cast<int>(t));
  }

  BodySample out;
  const Emitter surface(out, 0);
  for (int r : face_order) sample_face(tris, faces_by_root[r], welded, dx, surface);
  if (interior_layers == 0) return out;

  // Interior: lattice points box_lo + (i, j, k) dx in the band dx/2 <= d < layers dx + dx/2.
  const double band = interior_layers * dx + 0.5 * dx;
  std::array<std::int64_t, 3> n;
  for (int a = 0; a < 3; ++a) {
    n[a] = static_cast<std::int64_t>(std::floor((box_hi[a] - box_lo[a]) / dx)) + 1;
  }
  auto key_of = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
    return i + n[0] * (j + n[1] * k);
  };
  auto point_of = [&](std::int64_t key) {
    const std::int64_t i = key % n[0], j = (key / n[0]) % n[1], k = key / (n[0] * n[1]);
    return Vec3(box_lo[0] + i * dx, box_lo[1] + j * dx, box_lo[2] + k * dx);
  };
  std::unordered_map<std::int64_t, double> distance;
  for (const MeshTriangle& t : tris) {
    std::array<std::int64_t, 3> first, last;
    for (int a = 0; a < 3; ++a) {
      const double tlo = std::min({t.a[a], t.b[a], t.c[a]}) - band - box_lo[a];
      const double thi = std::max({t.a[a], t.b[a], t.c[a]}) + band - box_lo[a];
      first[a] = std::max<std::int64_t>(0, static_cast<std::int64_t>(std::ceil(tlo / dx)));
      last[a] = std::min<std::int64_t>(n[a] - 1, static_cast<std::int64_t>(std::floor(thi / dx)));
    }
    for (std::int64_t k = first[2]; k <= last[2]; ++k) {
      for (std::int64_t j = first[1]; j <= last[1]; ++j) {
        for (std::int64_t i = first[0]; i <= last[0]; ++i) {
          const std::int64_t key = key_of(i, j, k);
          const Vec3 p = point_of(key);
          const double d = (closest_on_triangle(p, t.a, t.b, t.c) - p).norm();
          if (d >= band) continue;
          const auto [it, fresh] = distance.try_emplace(key, d);
          if (!fresh) it->second = std::min(it->second, d);
        }
      }
    }
  }
  std::vector<std::pair<std::int64_t, double>> candidates;
  for (const auto& [key, d] : distance) {
    if (d >= 0.5 * dx) candidates.emplace_back(key, d);
  }
  std::sort(candidates.begin(), candidates.end());
  std::unordered_map<std::int64_t, std::size_t> index_of;
  for (std::size_t c = 0; c < candidates.size(); ++c) index_of[candidates[c].first] = c;

  // Inside or not: the winding number, computed once per group of candidates joined by lattice
  // steps between points farther than dx/2 from the surface (such a step cannot cross it).
  auto winding = [&](const Vec3& p) {
    double sum = 0;
    for (const MeshTriangle& t : tris) sum += solid_angle(p, t.a, t.b, t.c);
    return sum / (4 * kPi);
  };
  const double free_distance = 0.5 * dx * (1 + 1e-9);
  std::vector<int> inside(candidates.size(), -1);
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (inside[c] >= 0) continue;
    const int status = winding(point_of(candidates[c].first)) > 0.5 ? 1 : 0;
    inside[c] = status;
    if (candidates[c].second <= free_distance) continue;
    std::vector<std::size_t> stack = {c};
    while (!stack.empty()) {
      const std::int64_t key = candidates[stack.back()].first;
      stack.pop_back();
      const std::int64_t i = key % n[0], j = (key / n[0]) % n[1], k = key / (n[0] * n[1]);
      const std::array<std::array<std::int64_t, 3>, 6> steps = {{{i - 1, j, k},
                                                                 {i + 1, j, k},
                                                                 {i, j - 1, k},
                                                                 {i, j + 1, k},
                                                                 {i, j, k - 1},
                                                                 {i, j, k + 1}}};
      for (const auto& s : steps) {
        if (s[0] < 0 || s[1] < 0 || s[2] < 0 || s[0] >= n[0] || s[1] >= n[1] || s[2] >= n[2]) {
          continue;
        }
        const auto it = index_of.find(key_of(s[0], s[1], s[2]));
        if (it == index_of.end()) continue;
        const std::size_t m = it->second;
        if (inside[m] >= 0 || candidates[m].second <= free_distance) continue;
        inside[m] = status;
        stack.push_back(m);
      }
    }
  }
  for (int layer = 1; layer <= interior_layers; ++layer) {  // grouped by layer, lattice order
    const Emitter emit(out, layer);
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      const int l =
          std::clamp(static_cast<int>(std::lround(candidates[c].second / dx)), 1, interior_layers);
      if (inside[c] == 1 && l == layer) emit(point_of(candidates[c].first));
    }
  }
  return out;
}

}  // namespace sluice
