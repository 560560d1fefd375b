#include "sluice/geometry/body_sampling.hpp"

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

namespace sluice {

std::size_t BodySample::surface_count() const {
  return static_cast<std::size_t>(std::count(layer.begin(), layer.end(), 0));
}

namespace {

constexpr double kPi = 3.14159265358979323846;
// Most cells along one length; far beyond anything a simulation can hold, it only keeps the
// integer arithmetic below safe.
constexpr double kMaxCells = 1e7;

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

bool positive_finite(double v) {
  return std::isfinite(v) && v > 0;
}

void check_common(const std::string& fn, double dx, int interior_layers, int dimension) {
  require(positive_finite(dx), fn + ": dx must be positive and finite");
  require(interior_layers >= 0, fn + ": interior_layers must be >= 0");
  require(dimension == 2 || dimension == 3, fn + ": dimension must be 2 or 3");
}

void check_size(const std::string& fn, const char* what, double value, double dx) {
  require(positive_finite(value), fn + ": " + what + " must be positive and finite");
  require(value / dx < kMaxCells, fn + ": " + what + " is too many spacings dx long");
}

// Equal cells of about dx along a length (at least one).
int cell_count(double length, double dx) {
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
constexpr double kCollapse = 0.5;
constexpr double kSlack = 1e-9;

// ---------------------------------------------------------------------------------------------
// Box

// The model's axes in 3D numbering (2D: x and z).
std::vector<int> model_axes(int dimension) {
  return dimension == 2 ? std::vector<int>{0, 2} : std::vector<int>{0, 1, 2};
}

// Calls fn(point, cell measure) at the centres of the equal cells that tile the extents
// `e` along `axes` (centred at the origin; other coordinates zero). No axes: one call at 0.
void for_each_cell(const Vec3& e, const std::vector<int>& axes, double dx,
                   const std::function<void(const Vec3&, double)>& fn) {
  std::vector<int> count;
  std::vector<double> step;
  double measure = 1;
  for (int a : axes) {
    count.push_back(cell_count(e[a], dx));
    step.push_back(e[a] / count.back());
    measure *= step.back();
  }
  std::vector<int> index(axes.size(), 0);
  while (true) {
    Vec3 p = Vec3::Zero();
    for (std::size_t k = 0; k < axes.size(); ++k) {
      p[axes[k]] = -0.5 * e[axes[k]] + (index[k] + 0.5) * step[k];
    }
    fn(p, measure);
    std::size_t k = 0;
    while (k < axes.size() && ++index[k] == count[k]) index[k++] = 0;
    if (k == axes.size()) return;
  }
}

// The closed surface of the box of extents `e` centred at the origin: per face (x-, x+, y-, ...)
// the cell centres of that face, with its normal.
void emit_box_surface(const Vec3& e, const std::vector<int>& axes, double dx, const Emitter& emit) {
  for (int a : axes) {
    std::vector<int> tangent;
    for (int b : axes) {
      if (b != a) tangent.push_back(b);
    }
    for (double sign : {-1.0, 1.0}) {
      Vec3 n = Vec3::Zero();
      n[a] = sign;
      for_each_cell(e, tangent, dx, [&](const Vec3& c, double measure) {
        Vec3 p = c;
        p[a] = 0.5 * sign * e[a];
        emit(p, n, measure);
      });
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Sphere and circle

// The circle of radius rho in the x-z plane: n equal arcs, a particle at the middle of each.
void emit_circle(double rho, double dx, const Emitter& emit) {
  const int n = std::max(3, static_cast<int>(std::lround(2 * kPi * rho / dx)));
  const double offset = 0.5 * (emit.layer() % 2);  // stagger successive rings
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * (i + offset) / n;
    const Vec3 u(std::cos(t), 0.0, std::sin(t));
    emit(rho * u, u, 2 * kPi * rho / n);
  }
}

// Golden-spiral unit vectors: z evenly spaced, longitude advancing by the golden angle.
std::vector<Vec3> golden_spiral(int n) {
  const double golden_angle = kPi * (3 - std::sqrt(5.0));
  std::vector<Vec3> out;
  out.reserve(n);
  for (int i = 0; i < n; ++i) {
    const double z = 1 - (2.0 * i + 1) / n;
    const double r = std::sqrt(std::max(0.0, 1 - z * z));
    const double phi = golden_angle * i;
    out.push_back(Vec3(r * std::cos(phi), r * std::sin(phi), z).normalized());
  }
  return out;
}

// The sphere of radius rho. Areas (surface only): 4 pi rho^2 / N times (1 + c.(n_i - mean n)),
// with c the smallest correction that makes sum a_i n_i zero; the sum of the areas is unchanged
// because the deviations from the mean normal add up to zero.
void emit_sphere(double rho, double dx, const Emitter& emit) {
  const double total = 4 * kPi * rho * rho;
  const int n = std::max(4, static_cast<int>(std::lround(total / (dx * dx))));
  const std::vector<Vec3> u = golden_spiral(n);
  Vec3 sum = Vec3::Zero();
  for (const Vec3& v : u) sum += v;
  const Vec3 mean = sum / n;
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const Vec3& v : u) scatter += (v - mean) * (v - mean).transpose();
  const Vec3 c = scatter.ldlt().solve(-sum);
  for (const Vec3& v : u) emit(rho * v, v, total / n * (1 + c.dot(v - mean)));
}

// ---------------------------------------------------------------------------------------------
// Cylinder

// The flat disc of radius rho at height z: rings of width w = rho / round(rho/dx), ring k cut
// into m_k equal sectors (area pi w^2 (2k+1) / m_k), a particle in each at the ring's mid radius
// (a single sector of the central ring sits at the centre).
void emit_disc(double rho, double z, const Vec3& n, double dx, const Emitter& emit) {
  const int rings = cell_count(rho, dx);
  const double w = rho / rings;
  for (int k = 0; k < rings; ++k) {
    const int m = std::max(1, static_cast<int>(std::lround(2 * kPi * (k + 0.5) * w / dx)));
    const double area = kPi * w * w * (2 * k + 1) / m;
    const double radius = (k == 0 && m == 1) ? 0.0 : (k + 0.5) * w;
    for (int j = 0; j < m; ++j) {
      const double t = 2 * kPi * (j + 0.5 * (k % 2)) / m;
      emit(Vec3(radius * std::cos(t), radius * std::sin(t), z), n, area);
    }
  }
}

// The side of the cylinder of radius rho and length len (axis z): particles at the centres of
// an n_theta by n_z grid of equal cells.
void emit_cylinder_side(double rho, double len, double dx, const Emitter& emit) {
  const int n_theta = std::max(3, static_cast<int>(std::lround(2 * kPi * rho / dx)));
  const int n_z = cell_count(len, dx);
  const double area = (2 * kPi * rho / n_theta) * (len / n_z);
  for (int j = 0; j < n_z; ++j) {
    const double z = -0.5 * len + (j + 0.5) * len / n_z;
    for (int i = 0; i < n_theta; ++i) {
      const double t = 2 * kPi * (i + 0.5) / n_theta;
      const Vec3 u(std::cos(t), std::sin(t), 0.0);
      emit(Vec3(rho * u[0], rho * u[1], z), u, area);
    }
  }
}

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

BodySample sample_box_body(const Vec3& size, double dx, int interior_layers, int dimension) {
  const std::string fn = "sample_box_body";
  check_common(fn, dx, interior_layers, dimension);
  const std::vector<int> axes = model_axes(dimension);
  for (int a : axes) check_size(fn, "size", size[a], dx);

  BodySample out;
  emit_box_surface(size, axes, dx, Emitter(out, 0));
  for (int k = 1; k <= interior_layers; ++k) {
    Vec3 e = Vec3::Zero();
    std::vector<int> thick;  // axes along which the layer keeps two faces
    bool fits = true;
    for (int a : axes) {
      e[a] = size[a] - 2 * k * dx;
      if (e[a] <= -kCollapse * dx * (1 - kSlack)) fits = false;
      if (e[a] >= kCollapse * dx) {
        thick.push_back(a);
      } else {
        e[a] = 0;
      }
    }
    if (!fits) break;
    const Emitter emit(out, k);
    if (thick.size() == axes.size()) {
      emit_box_surface(e, axes, dx, emit);
    } else {  // flat: a sheet, a line or a point
      for_each_cell(e, thick, dx, [&](const Vec3& p, double) { emit(p); });
    }
  }
  return out;
}

BodySample sample_sphere_body(double radius, double dx, int interior_layers, int dimension) {
  const std::string fn = "sample_sphere_body";
  check_common(fn, dx, interior_layers, dimension);
  check_size(fn, "radius", radius, dx);
  require(dimension == 2 || radius / dx < 1e4, fn + ": radius is too many spacings dx long");

  BodySample out;
  auto shell = [&](double rho, const Emitter& emit) {
    if (dimension == 2) {
      emit_circle(rho, dx, emit);
    } else {
      emit_sphere(rho, dx, emit);
    }
  };
  shell(radius, Emitter(out, 0));
  for (int k = 1; k <= interior_layers; ++k) {
    const double rho = radius - k * dx;
    if (rho <= -0.5 * kCollapse * dx * (1 - kSlack)) break;
    if (rho < 0.5 * kCollapse * dx) {
      Emitter(out, k)(Vec3::Zero());
      break;
    }
    shell(rho, Emitter(out, k));
  }
  return out;
}

BodySample sample_cylinder_body(double radius, double length, double dx, int interior_layers,
                                int dimension) {
  const std::string fn = "sample_cylinder_body";
  check_common(fn, dx, interior_layers, dimension);
  if (dimension == 2) return sample_sphere_body(radius, dx, interior_layers, 2);
  check_size(fn, "radius", radius, dx);
  check_size(fn, "length", length, dx);

  BodySample out;
  auto closed = [&](double rho, double len, const Emitter& emit) {
    emit_cylinder_side(rho, len, dx, emit);
    emit_disc(rho, -0.5 * len, Vec3(0, 0, -1), dx, emit);
    emit_disc(rho, 0.5 * len, Vec3(0, 0, 1), dx, emit);
  };
  closed(radius, length, Emitter(out, 0));
  for (int k = 1; k <= interior_layers; ++k) {
    const double rho = radius - k * dx;
    const double len = length - 2 * k * dx;
    if (rho <= -0.5 * kCollapse * dx * (1 - kSlack) || len <= -kCollapse * dx * (1 - kSlack)) {
      break;
    }
    const bool thin_radius = rho < 0.5 * kCollapse * dx;
    const bool thin_length = len < kCollapse * dx;
    const Emitter emit(out, k);
    if (!thin_radius && !thin_length) {
      closed(rho, len, emit);
    } else if (!thin_radius) {
      emit_disc(rho, 0.0, Vec3::Zero(), dx, emit);
    } else if (!thin_length) {
      for_each_cell(Vec3(0, 0, len), {2}, dx, [&](const Vec3& p, double) { emit(p); });
    } else {
      emit(Vec3::Zero());
    }
  }
  return out;
}

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
