#include "sluice/rigid/joined_mobility.hpp"

namespace sluice {

namespace {

Eigen::MatrixXd inverse_mass_of(const std::vector<Mat6>& own) {
  const auto n = static_cast<Eigen::Index>(6 * own.size());
  Eigen::MatrixXd inverse_mass = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t b = 0; b < own.size(); ++b) {
    inverse_mass.block<6, 6>(static_cast<Eigen::Index>(6 * b), static_cast<Eigen::Index>(6 * b)) =
        own[b];
  }
  return inverse_mass;
}

// J: one line per row, 6 columns per body; a side on a body beyond `bodies` moves nothing.
Eigen::MatrixXd jacobian_of(const RowGroup& rows, std::size_t bodies) {
  const auto count = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(count, static_cast<Eigen::Index>(6 * bodies));
  for (Eigen::Index r = 0; r < count; ++r) {
    const ConstraintRow& row = rows.rows()[static_cast<std::size_t>(r)];
    const auto put = [&](std::size_t body, const Vec3& linear, const Vec3& angular) {
      if (body >= bodies) return;  // the world, or a wall
      const auto column = static_cast<Eigen::Index>(6 * body);
      jacobian.block<1, 3>(r, column) += linear.transpose();
      jacobian.block<1, 3>(r, column + 3) += angular.transpose();
    };
    put(row.a, row.linear_a, row.angular_a);
    put(row.b, row.linear_b, row.angular_b);
  }
  return jacobian;
}

}  // namespace

Eigen::MatrixXd joined_mobility(const std::vector<Mat6>& own, const RowGroup& joints) {
  const Eigen::MatrixXd inverse_mass = inverse_mass_of(own);
  if (joints.size() == 0) return inverse_mass;
  const Eigen::MatrixXd jacobian = jacobian_of(joints, own.size());
  const Eigen::MatrixXd moved = inverse_mass * jacobian.transpose();  // M^-1 J^T
  const Eigen::MatrixXd delassus = jacobian * moved;                  // J M^-1 J^T
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> inverse(delassus);
  return inverse_mass - moved * inverse.solve(moved.transpose());
}

std::vector<Real> row_impulses(const std::vector<Mat6>& own, const RowGroup& rows,
                               const Eigen::VectorXd& impulse) {
  if (rows.size() == 0) return {};
  const Eigen::MatrixXd inverse_mass = inverse_mass_of(own);
  const Eigen::MatrixXd jacobian = jacobian_of(rows, own.size());
  const Eigen::MatrixXd moved = inverse_mass * jacobian.transpose();
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> inverse(jacobian * moved);
  const Eigen::VectorXd lambda = -inverse.solve(moved.transpose() * impulse);
  return {lambda.data(), lambda.data() + lambda.size()};
}

}  // namespace sluice
