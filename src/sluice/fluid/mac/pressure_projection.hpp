// The pressure projection: the face velocities made divergence-free in the water, with the
// free surface as a Dirichlet condition p = 0 placed where phi crosses zero between a water
// and an air cell (the ghost fluid method of Gibou, Fedkiw, Cheng & Kang, JCP 176, 2002), and
// solids through the open fraction of each face, the solid's velocity filling the rest (the
// variational approach of Batty, Bertails & Bridson, SIGGRAPH 2007, which Ng, Min & Gibou,
// JCP 228, 2009 show second order for the cut-cell Poisson problem). The matrix is symmetric
// positive definite and goes to one of linear/'s solvers.
#pragma once

#include <memory>
#include <vector>

#include "sluice/fluid/mac/mac_grid.hpp"
#include "sluice/fluid/mac/velocity_extension.hpp"
#include "sluice/linear/sparse_solver.hpp"

namespace sluice {

// What a face of the grid is made of: the fraction of it open to the fluid (0: inside a
// solid) and the solid's velocity component there.
template <int D>
struct SolidFaces {
  FaceField<D> open;
  FaceField<D> velocity;
  std::array<std::vector<int>, D> body;  // the body whose velocity a face has, or -1
  // On the grid's boundary, an outlet's pressure [Pa] beyond the face, held on the face itself;
  // NaN, or no values at all: none (fluid/mac/open_boundaries.hpp).
  FaceField<D> outlet_pressure;
};

// A body in the projection: its velocity (linear, angular) is an unknown of the pressure
// problem, so that the pressure that keeps the water divergence-free is the one that also
// accelerates the body (Batty, Bertails & Bridson 2007): the added mass is in the solve, and a
// body lighter than the water it moves stays stable.
struct ProjectedBody {
  Vec3 centre = Vec3::Zero();    // of mass
  Mat6 mobility = Mat6::Zero();  // the inverse of its generalised mass (world), 0: immobile
  Vec6 velocity = Vec6::Zero();  // in: before the pressure's impulse; out: after it
  Vec6 load = Vec6::Zero();      // out: the pressure's force and moment about `centre`
};

struct ProjectionReport {
  std::size_t unknowns = 0;
  int iterations = 0;
  double relative_residual = 0;
  bool converged = true;
};

template <int D>
class PressureProjection {
 public:
  explicit PressureProjection(std::unique_ptr<SparseSolver> solver) : solver_(std::move(solver)) {}

  // Projects `u` over a step `dt` for water of `density`; `pressure` [Pa] receives the
  // pressure of every water cell (0 elsewhere) and `valid` marks the faces set here (beside
  // a water cell, or closed by a solid). Water cells are those with phi < 0 and a face open.
  // The faces of `bodies` (solid.body) move with the bodies' velocities, solved for with the
  // pressure where a body is mobile; each body's load is the pressure's force on it. With
  // `joined` (6 rows and columns per body: BodyGeometry::joined_mobility), the bodies answer
  // the pressure through it, joints kept, and their own `mobility` is not read.
  ProjectionReport project(const MacGrid<D>& grid, const CellField& phi, const SolidFaces<D>& solid,
                           Real dt, Real density, FaceField<D>& u, CellField& pressure,
                           FaceMarks<D>& valid, std::vector<ProjectedBody>& bodies,
                           const Eigen::MatrixXd* joined = nullptr);

  // Checkpoints: the warm start.
  void archive_state(StateArchive& a) { a(last_solution_); }

 private:
  std::unique_ptr<SparseSolver> solver_;
  std::vector<int> unknown_;       // per cell: its row, or -1
  Eigen::VectorXd last_solution_;  // p dt / (rho h) of the last step per cell: warm start
};

// The fraction of the segment from value a to value b of a level that lies where it is >= 0.
inline Real positive_fraction(Real a, Real b) {
  if (a >= 0 && b >= 0) return 1;
  if (a < 0 && b < 0) return 0;
  return std::max(a, b) / std::abs(a - b);
}

}  // namespace sluice
