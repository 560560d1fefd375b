// Surface and interior particles of the analytic shapes: boxes, spheres and cylinders.
#include <Eigen/Cholesky>
#include <functional>
#include <vector>

#include "sluice/geometry/body_sampling.hpp"
#include "sluice/geometry/body_sampling_support.hpp"

namespace sluice {

using namespace body_sampling;

std::size_t BodySample::surface_count() const {
  return static_cast<std::size_t>(std::count(layer.begin(), layer.end(), 0));
}

namespace {

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

}  // namespace sluice
