// Velocity constraints solved by projected Gauss-Seidel: a unilateral row stops an approach and
// lets a separation go, an equality row between two bodies keeps their momentum, and a row at
// an offset point turns the body as well as moving it.
#include "sluice/rigid/constraint_solver.hpp"

#include <gtest/gtest.h>

namespace sluice {
namespace {

SystemBody body(double mass, const Vec3& velocity) {
  SystemBody b;
  b.state.mass = mass;
  b.state.principal_inertia = Vec3::Constant(0.1 * mass);
  b.state.velocity = velocity;
  return b;
}

ConstraintRow unilateral_up(std::size_t a) {
  ConstraintRow r;
  r.a = a;
  r.linear_a = Vec3::UnitZ();
  r.lower = 0;  // it may push up, never pull down
  return r;
}

TEST(ConstraintSolver, UnilateralRowStopsAnApproachAndFreesASeparation) {
  std::vector<SystemBody> bodies{body(2.0, Vec3(0.3, 0, -0.5))};
  std::vector<ConstraintRow> rows{unilateral_up(0)};
  const ConstraintSolution s = solve_constraints(bodies, rows);
  EXPECT_NEAR(bodies[0].state.velocity[2], 0, 1e-15);
  EXPECT_NEAR(bodies[0].state.velocity[0], 0.3, 1e-15);  // frictionless: tangential kept
  EXPECT_NEAR(rows[0].impulse, 1.0, 1e-15);              // m |v_n|
  EXPECT_LE(s.iterations, 2);
  // Moving away: no impulse.
  std::vector<SystemBody> leaving{body(2.0, Vec3(0, 0, 0.5))};
  std::vector<ConstraintRow> again{unilateral_up(0)};
  solve_constraints(leaving, again);
  EXPECT_EQ(again[0].impulse, 0);
  EXPECT_EQ(leaving[0].state.velocity[2], 0.5);
}

TEST(ConstraintSolver, EqualityBetweenTwoBodiesKeepsMomentum) {
  std::vector<SystemBody> bodies{body(1.0, Vec3(1, 0, 0)), body(3.0, Vec3(-1, 0, 0))};
  ConstraintRow r;
  r.a = 0;
  r.b = 1;
  r.linear_a = Vec3::UnitX();
  r.linear_b = -Vec3::UnitX();  // v_a,x - v_b,x = 0
  std::vector<ConstraintRow> rows{r};
  solve_constraints(bodies, rows);
  EXPECT_NEAR(bodies[0].state.velocity[0], -0.5, 1e-14);  // the common velocity
  EXPECT_NEAR(bodies[1].state.velocity[0], -0.5, 1e-14);
  EXPECT_NEAR(bodies[0].state.velocity[0] * 1 + bodies[1].state.velocity[0] * 3, -2, 1e-14);
}

TEST(ConstraintSolver, OffsetRowTurnsTheBody) {
  // A row at the point r = (0.1, 0, 0) of a body moving down: the point's normal velocity
  // v_z + (w x r)_z is stopped, shared between translation and rotation.
  std::vector<SystemBody> bodies{body(1.0, Vec3(0, 0, -1))};
  ConstraintRow r = unilateral_up(0);
  const Vec3 arm(0.1, 0, 0);
  r.angular_a = arm.cross(Vec3::UnitZ());
  std::vector<ConstraintRow> rows{r};
  solve_constraints(bodies, rows);
  const RigidBody& s = bodies[0].state;
  EXPECT_NEAR(s.velocity[2] + s.angular_velocity().cross(arm)[2], 0, 1e-14);
  EXPECT_GT(s.velocity[2], -1);
  EXPECT_NE(s.angular_velocity().norm(), 0);
  // Fixed bodies do not move; a row on them alone is skipped.
  std::vector<SystemBody> wall{body(1.0, Vec3(0, 0, -1))};
  wall[0].fixed = true;
  std::vector<ConstraintRow> on_wall{unilateral_up(0)};
  solve_constraints(wall, on_wall);
  EXPECT_EQ(wall[0].state.velocity[2], -1);
}

}  // namespace
}  // namespace sluice
