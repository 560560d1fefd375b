// How bodies joined by joints answer impulses together. With each body's own mobility M_b^-1 (its
// inverse mass and inertia, 6 x 6, world, zero where it is immobile) on the diagonal of M^-1,
// and the joints' rows J (one velocity each that the joint forbids), an impulse P on the bodies
// changes their velocities by
//   W P,   W = M^-1 - M^-1 J^T (J M^-1 J^T)^+ J M^-1,
// the change that keeps J's velocities as they were (Lagrange multipliers eliminated; the
// pseudo-inverse takes redundant rows and rows on immobile bodies). A fluid that solves the
// bodies' velocities with its pressure (the grid's projection) needs W: with M^-1 alone, the
// water would push a wheel off its axle.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "sluice/ccp/row_group.hpp"

namespace sluice {

// W for the bodies whose own mobilities are `own` (linear, then angular, per body), joined by
// the equality rows of `joints`; a row's side on a body beyond `own` (a wall) or on the world
// moves nothing.
Eigen::MatrixXd joined_mobility(const std::vector<Mat6>& own, const RowGroup& joints);

// The rows' impulses lambda that keep their velocities while `impulse` (6 per body) acts:
// J M^-1 (impulse + J^T lambda) = 0, the least-squares lambda where rows are redundant. A row's
// impulse acts along its Jacobian on body b (on a, against it).
std::vector<Real> row_impulses(const std::vector<Mat6>& own, const RowGroup& rows,
                               const Eigen::VectorXd& impulse);

}  // namespace sluice
