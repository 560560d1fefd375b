#include "sluice/rigid/joined_mobility.hpp"

namespace sluice {

Eigen::MatrixXd joined_mobility(const std::vector<Mat6>& own, const RowGroup& joints) {
  const auto n = static_cast<Eigen::Index>(6 * own.size());
  Eigen::MatrixXd inverse_mass = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t b = 0; b < own.size(); ++b) {
    inverse_mass.block<6, 6>(static_cast<Eigen::Index>(6 * b), static_cast<Eigen::Index>(6 * b)) =
        own[b];
  }
  const auto rows = static_cast<Eigen::Index>(joints.size());
  if (rows == 0) return inverse_mass;
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(rows, n);
  for (Eigen::Index r = 0; r < rows; ++r) {
    const ConstraintRow& row = joints.rows()[static_cast<std::size_t>(r)];
    const auto put = [&](std::size_t body, const Vec3& linear, const Vec3& angular) {
      if (body >= own.size()) return;  // the world, or a wall
      const auto column = static_cast<Eigen::Index>(6 * body);
      jacobian.block<1, 3>(r, column) += linear.transpose();
      jacobian.block<1, 3>(r, column + 3) += angular.transpose();
    };
    put(row.a, row.linear_a, row.angular_a);
    put(row.b, row.linear_b, row.angular_b);
  }
  const Eigen::MatrixXd moved = inverse_mass * jacobian.transpose();  // M^-1 J^T
  const Eigen::MatrixXd delassus = jacobian * moved;                  // J M^-1 J^T
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> inverse(delassus);
  return inverse_mass - moved * inverse.solve(moved.transpose());
}

}  // namespace sluice
