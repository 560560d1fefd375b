// How bodies joined by joints answer an impulse together (rigid/joined_mobility.hpp), against
// what the joined bodies must do as one: a fixed joint makes two bodies one body, a revolute
// joint to the world leaves only the turn about its axis.
#include "sluice/rigid/joined_mobility.hpp"

#include <gtest/gtest.h>

#include "sluice/rigid/joint.hpp"

namespace sluice {
namespace {

SystemBody cube(const Vec3& position, double mass, double side) {
  SystemBody body;
  body.state.position = position;
  body.state.mass = mass;
  body.state.principal_inertia = Vec3::Constant(mass * side * side / 6);
  return body;
}

Mat6 own_mobility(const SystemBody& body) {
  Mat6 m = Mat6::Zero();
  m.topLeftCorner<3, 3>() = Eigen::Matrix3d::Identity() / body.state.mass;
  m.bottomRightCorner<3, 3>() = body.state.inverse_world_inertia();
  return m;
}

Eigen::MatrixXd joined(const std::vector<SystemBody>& bodies, const Joint& joint) {
  RowGroup rows;
  add_joint_rows(joint, bodies, 1.0, 0.0, rows);
  std::vector<Mat6> own;
  for (const SystemBody& b : bodies) own.push_back(own_mobility(b));
  return joined_mobility(own, rows);
}

TEST(JoinedMobility, WithoutJointsEachBodyAnswersAlone) {
  const std::vector<Mat6> own = {2 * Mat6::Identity(), 3 * Mat6::Identity()};
  const Eigen::MatrixXd w = joined_mobility(own, RowGroup());
  EXPECT_TRUE((w.block<6, 6>(0, 0)).isApprox(own[0]));
  EXPECT_TRUE((w.block<6, 6>(6, 6)).isApprox(own[1]));
  EXPECT_TRUE((w.block<6, 6>(0, 6)).isZero());
}

// Two cubes side by side, welded: a push on one moves both at the push over their summed mass,
// and a push off their common centre turns them together about it.
TEST(JoinedMobility, AFixedJointMakesTwoBodiesOne) {
  const std::vector<SystemBody> bodies = {cube(Vec3(0, 0, 0), 2.0, 0.1),
                                          cube(Vec3(0.1, 0, 0), 6.0, 0.1)};
  const Joint weld = make_joint(JointType::kFixed, 0, 1, bodies, Vec3(0.05, 0, 0), Vec3::UnitZ());
  const Eigen::MatrixXd w = joined(bodies, weld);
  Eigen::VectorXd push = Eigen::VectorXd::Zero(12);
  push[2] = 8.0;  // 8 N s upwards on the light cube's centre
  const Eigen::VectorXd dv = w * push;
  // The pair's centre of mass (x = 0.075 m) rises at 8 / 8 = 1 m/s; the push, 0.075 m to its
  // -x side, turns the pair about +y at 8 * 0.075 / I, I about the common centre.
  const double total = 8.0, lever = 0.075;
  const double inertia =
      2.0 * 0.01 / 6 + 6.0 * 0.01 / 6 + 2.0 * 0.075 * 0.075 + 6.0 * 0.025 * 0.025;
  const double turn = push[2] * lever / inertia;
  EXPECT_NEAR(dv[4], turn, 1e-9);      // body 0's angular velocity about y
  EXPECT_NEAR(dv[6 + 4], turn, 1e-9);  // body 1's, the same
  EXPECT_NEAR(dv[2], push[2] / total + lever * turn, 1e-9);
  EXPECT_NEAR(dv[6 + 2], push[2] / total - 0.025 * turn, 1e-9);
  EXPECT_NEAR(dv[0], 0.0, 1e-9);
  EXPECT_NEAR(dv[6], 0.0, 1e-9);
  // W is symmetric (reciprocity) and keeps the weld's velocities: the rows see no change.
  EXPECT_TRUE(w.isApprox(w.transpose(), 1e-12));
}

// A wheel on an axle fixed in the world: any impulse only turns it about the axle.
TEST(JoinedMobility, ARevoluteJointToTheWorldLeavesTheTurnAboutItsAxis) {
  const std::vector<SystemBody> bodies = {cube(Vec3(1, 2, 3), 4.0, 0.2)};
  const Joint axle = make_joint(JointType::kRevolute, ConstraintRow::kWorld, 0, bodies,
                                Vec3(1, 2, 3), Vec3::UnitY());
  const Eigen::MatrixXd w = joined(bodies, axle);
  Eigen::VectorXd impulse(6);
  impulse << 1.0, -2.0, 3.0, 0.5, 0.7, -0.2;
  const Eigen::VectorXd dv = w * impulse;
  EXPECT_NEAR(dv.head<3>().norm(), 0.0, 1e-12);
  EXPECT_NEAR(dv[3], 0.0, 1e-12);
  EXPECT_NEAR(dv[5], 0.0, 1e-12);
  EXPECT_NEAR(dv[4], 0.7 / (4.0 * 0.04 / 6), 1e-9);
}

// A cube on the world's floor, one row along +z at its centre: pushed down by 2 N s, the row
// holds it with +2 N s (it pushes back); pushed up, with -2 N s (it would have to pull). Two
// rows on the same velocity share the impulse (the least-squares answer).
TEST(JoinedMobility, RowImpulsesHoldTheRowsVelocities) {
  const std::vector<Mat6> own = {Mat6::Identity() / 4.0};
  ConstraintRow floor;
  floor.a = 1;  // the world
  floor.b = 0;
  floor.linear_b = Vec3::UnitZ();
  floor.linear_a = -Vec3::UnitZ();
  RowGroup rows;
  rows.add_row(floor);
  Eigen::VectorXd down = Eigen::VectorXd::Zero(6);
  down[2] = -2;
  EXPECT_NEAR(row_impulses(own, rows, down)[0], 2, 1e-12);
  EXPECT_NEAR(row_impulses(own, rows, -down)[0], -2, 1e-12);
  rows.add_row(floor);
  const std::vector<Real> shared = row_impulses(own, rows, down);
  EXPECT_NEAR(shared[0], 1, 1e-12);
  EXPECT_NEAR(shared[1], 1, 1e-12);
}

}  // namespace
}  // namespace sluice
