#include "sluice/fluid/mac/pressure_projection.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

#include "sluice/exec/policy.hpp"

namespace sluice {

namespace {

// Smallest fraction of a cell at which the ghost-fluid interface is placed: closer, and the
// matrix's diagonal grows without bound (Gibou et al. clamp it alike).
constexpr Real kSmallestTheta = 1e-3;

// Where between a water cell (phi_water < 0) and the air beyond (phi_air >= 0) the interface
// lies, as a fraction of the way; beyond the grid's open boundary, air half a cell out.
inline Real theta_towards_air(Real phi_water, Real phi_air) {
  return std::max(kSmallestTheta, phi_water / (phi_water - phi_air));
}

}  // namespace

template <int D>
ProjectionReport PressureProjection<D>::project(const MacGrid<D>& grid, const CellField& phi,
                                                const SolidFaces<D>& solid, Real dt, Real density,
                                                FaceField<D>& u, CellField& pressure,
                                                FaceMarks<D>& valid,
                                                std::vector<ProjectedBody>& bodies,
                                                const Eigen::MatrixXd* joined) {
  const Lattice<D> cells = grid.cell_lattice();
  const std::size_t n = cells.size();
  std::array<Lattice<D>, D> faces;
  for (int a = 0; a < D; ++a) faces[a] = grid.face_lattice(a);
  // The face of `axis` on `side` (0 lower, 1 upper) of cell c.
  auto face_of = [&](const GridIndex<D>& c, int axis, int side) {
    GridIndex<D> f = c;
    f[axis] += side;
    return faces[axis].index(f);
  };
  auto is_water = [&](std::size_t k) { return unknown_[k] >= 0; };
  // The body whose velocity a face has (or -1), and the face's row of the map from that body's
  // velocity (linear, angular) to the face's normal velocity.
  auto body_of = [&](int a, std::size_t f) {
    const int b = solid.body[a].empty() ? -1 : solid.body[a][f];
    return b >= 0 && static_cast<std::size_t>(b) < bodies.size() ? b : -1;
  };
  auto face_jacobian = [&](int a, std::size_t f, int b) {
    Vec<D> axis = Vec<D>::Zero();
    axis[a] = 1;
    const Vec3 e = to_3d<D>(axis);
    const Vec3 r = to_3d<D>(faces[a].position(faces[a].coordinates(f))) - bodies[b].centre;
    Vec6 j;
    j.head<3>() = e;
    j.tail<3>() = r.cross(e);
    return j;
  };
  auto solid_velocity = [&](int a, std::size_t f) {
    const int b = body_of(a, f);
    return b < 0 ? solid.velocity[a][f] : face_jacobian(a, f, b).dot(bodies[b].velocity);
  };
  // An outlet's pressure beyond a boundary face, scaled as the unknowns (p dt / (rho h)), or NaN.
  const Real scale = dt / (density * grid.h);
  auto outlet_of = [&](int a, std::size_t f) {
    return solid.outlet_pressure[a].empty() ? std::numeric_limits<Real>::quiet_NaN()
                                            : solid.outlet_pressure[a][f] * scale;
  };

  unknown_.assign(n, -1);
  int rows = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (!(phi[k] < 0)) continue;
    const GridIndex<D> c = cells.coordinates(k);
    bool open = false;
    for (int a = 0; a < D && !open; ++a)
      for (int side = 0; side < 2 && !open; ++side) open = solid.open[a][face_of(c, a, side)] > 0;
    if (open) unknown_[k] = rows++;
  }

  // Rows: sum over open faces of w (p_i - p_j), the air beyond the interface at theta.
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(static_cast<std::size_t>(rows) * (2 * D + 1));
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(rows);
  std::vector<char> touches_air(static_cast<std::size_t>(rows), 0);
  // G: each row's divergence per unit of each body's velocity.
  std::vector<Eigen::Triplet<double, int>> coupling;
  for (std::size_t k = 0; k < n; ++k) {
    const int row = unknown_[k];
    if (row < 0) continue;
    const GridIndex<D> c = cells.coordinates(k);
    double diagonal = 0, divergence = 0, rhs_outlet = 0;
    for (int a = 0; a < D; ++a) {
      for (int side = 0; side < 2; ++side) {
        const std::size_t f = face_of(c, a, side);
        const Real w = solid.open[a][f];
        const Real sign = side == 1 ? 1 : -1;
        divergence += sign * (w * u[a][f] + (1 - w) * solid_velocity(a, f));
        if (const int b = body_of(a, f); b >= 0 && w < 1) {
          const Vec6 j = face_jacobian(a, f, b);
          for (int k = 0; k < 6; ++k)
            if (j[k] != 0) coupling.emplace_back(row, 6 * b + k, sign * (1 - w) * j[k]);
        }
        if (w <= 0) continue;
        GridIndex<D> nb = c;
        nb[a] += side == 1 ? 1 : -1;
        if (cells.contains(nb) && is_water(cells.index(nb))) {
          diagonal += w;
          entries.emplace_back(row, unknown_[cells.index(nb)], -w);
        } else if (const Real q_out = outlet_of(a, f); !cells.contains(nb) && !std::isnan(q_out)) {
          // The outlet's pressure on the face, half a cell from the centre.
          diagonal += 2 * w;
          rhs_outlet += 2 * w * q_out;
          touches_air[static_cast<std::size_t>(row)] = 1;
        } else {
          const Real beyond = cells.contains(nb) ? phi[cells.index(nb)] : 0.5 * grid.h;
          diagonal += w / theta_towards_air(phi[k], std::max(beyond, Real(0)));
          touches_air[static_cast<std::size_t>(row)] = 1;
        }
      }
    }
    entries.emplace_back(row, row, diagonal);
    rhs[row] = rhs_outlet - divergence;
  }
  // A body of water with no free surface (a closed cavity) fixes its pressure's level at one
  // cell: the rows of a closed region sum to zero, so that cell's pressure is 0 exactly.
  std::vector<int> region(static_cast<std::size_t>(rows), -1);
  std::vector<std::size_t> stack;
  for (std::size_t k0 = 0; k0 < n; ++k0) {
    if (!is_water(k0) || region[static_cast<std::size_t>(unknown_[k0])] >= 0) continue;
    const int label = unknown_[k0];
    bool free_surface = false;
    stack.assign(1, k0);
    region[static_cast<std::size_t>(label)] = label;
    while (!stack.empty()) {
      const std::size_t k = stack.back();
      stack.pop_back();
      free_surface = free_surface || touches_air[static_cast<std::size_t>(unknown_[k])];
      const GridIndex<D> c = cells.coordinates(k);
      for (int a = 0; a < D; ++a) {
        for (int side = 0; side < 2; ++side) {
          GridIndex<D> nb = c;
          nb[a] += side == 1 ? 1 : -1;
          if (!cells.contains(nb) || solid.open[a][face_of(c, a, side)] <= 0) continue;
          const std::size_t m = cells.index(nb);
          if (!is_water(m) || region[static_cast<std::size_t>(unknown_[m])] >= 0) continue;
          region[static_cast<std::size_t>(unknown_[m])] = label;
          stack.push_back(m);
        }
      }
    }
    if (!free_surface) entries.emplace_back(label, label, 1.0);
  }

  SparseRows matrix(rows, rows);
  matrix.setFromTriplets(entries.begin(), entries.end());
  Eigen::VectorXd x(rows);
  const bool warm = last_solution_.size() == static_cast<Eigen::Index>(n);
  for (std::size_t k = 0; k < n; ++k)
    if (unknown_[k] >= 0) x[unknown_[k]] = warm ? last_solution_[static_cast<Eigen::Index>(k)] : 0;
  ProjectionReport report;
  report.unknowns = static_cast<std::size_t>(rows);
  auto solve = [&](const Eigen::VectorXd& b, Eigen::VectorXd& solution) {
    if (rows == 0 || b.squaredNorm() == 0) {
      solution.setZero();
      return;
    }
    const SolveReport r = solver_->solve(matrix, b, solution);
    report.iterations += r.iterations;
    report.relative_residual = std::max(report.relative_residual, r.relative_residual);
    report.converged = report.converged && r.converged;
  };
  solve(rhs, x);

  // The bodies: with G and W = rho h^D M^-1, the problem is (A + G W G^T) q = rhs, solved by
  // the Woodbury identity with one more solve of A per free direction of a body.
  const auto columns = static_cast<int>(6 * bodies.size());
  Eigen::SparseMatrix<double> g(rows, columns);
  g.setFromTriplets(coupling.begin(), coupling.end());
  const double cell_mass = density * std::pow(grid.h, D);
  Eigen::MatrixXd w = Eigen::MatrixXd::Zero(columns, columns);
  if (joined) {
    w = cell_mass * *joined;
  } else {
    for (std::size_t b = 0; b < bodies.size(); ++b)
      w.block<6, 6>(6 * b, 6 * b) = cell_mass * bodies[b].mobility;
  }
  // The free directions that the water touches; no room for the others (a grid's worth each).
  std::vector<int> free;
  for (int c = 0; c < columns; ++c)
    if (!w.col(c).isZero() && g.col(c).squaredNorm() > 0) free.push_back(c);
  if (!free.empty()) {
    Eigen::MatrixXd y = Eigen::MatrixXd::Zero(rows, columns);
    for (const int c : free) {
      Eigen::VectorXd column = Eigen::VectorXd(g.col(c)), solution = Eigen::VectorXd::Zero(rows);
      solve(column, solution);
      y.col(c) = solution;
    }
    const Eigen::MatrixXd gty = Eigen::MatrixXd(g.transpose() * y);
    const Eigen::MatrixXd s = Eigen::MatrixXd::Identity(columns, columns) + w * gty;
    x -= y * s.partialPivLu().solve(w * (g.transpose() * x));
  }
  const Eigen::VectorXd impulse = g.transpose() * x;  // per body: G_b^T q
  const Eigen::VectorXd joined_change =
      joined ? Eigen::VectorXd(w * impulse) : Eigen::VectorXd();  // every body's, joints kept
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const Vec6 gq = impulse.segment<6>(6 * b);
    if (joined) {
      bodies[b].velocity += joined_change.segment<6>(6 * b);
    } else {
      bodies[b].velocity += cell_mass * bodies[b].mobility * gq;
    }
    bodies[b].load = (cell_mass / dt) * gq;
  }

  // The scaled pressure p dt / (rho h) per cell, 0 outside the water.
  last_solution_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
  for (std::size_t k = 0; k < n; ++k)
    if (unknown_[k] >= 0) last_solution_[static_cast<Eigen::Index>(k)] = x[unknown_[k]];
  const Eigen::VectorXd& q = last_solution_;
  pressure.assign(n, 0);
  exec::Default::for_each_light(n, [&](std::size_t k) {
    pressure[k] = q[static_cast<Eigen::Index>(k)] * density * grid.h / dt;
  });

  for (int a = 0; a < D; ++a) {
    valid[a].assign(faces[a].size(), 0);
    exec::Default::for_each_light(faces[a].size(), [&](std::size_t f) {
      if (solid.open[a][f] <= 0) {
        u[a][f] = solid_velocity(a, f);
        valid[a][f] = 1;
        return;
      }
      GridIndex<D> lower = faces[a].coordinates(f), upper = lower;
      lower[a] -= 1;
      const bool has_lower = cells.contains(lower), has_upper = cells.contains(upper);
      const std::size_t kl = has_lower ? cells.index(lower) : 0;
      const std::size_t ku = has_upper ? cells.index(upper) : 0;
      const bool water_lower = has_lower && is_water(kl), water_upper = has_upper && is_water(ku);
      if (!water_lower && !water_upper) return;
      // Beside air, the ghost pressure that puts p = 0 on the interface; beyond an outlet, the
      // one that puts its pressure on the face.
      auto ghost = [&](std::size_t water, bool has_other, std::size_t other) {
        const Real q_water = q[static_cast<Eigen::Index>(water)];
        if (const Real q_out = outlet_of(a, f); !has_other && !std::isnan(q_out))
          return 2 * q_out - q_water;
        const Real beyond = has_other ? phi[other] : 0.5 * grid.h;
        const Real theta = theta_towards_air(phi[water], std::max(beyond, Real(0)));
        return q_water * (theta - 1) / theta;
      };
      const Real pl = water_lower ? q[static_cast<Eigen::Index>(kl)] : ghost(ku, has_lower, kl);
      const Real pu = water_upper ? q[static_cast<Eigen::Index>(ku)] : ghost(kl, has_upper, ku);
      u[a][f] -= pu - pl;
      valid[a][f] = 1;
    });
  }
  return report;
}

template class PressureProjection<2>;
template class PressureProjection<3>;

}  // namespace sluice
