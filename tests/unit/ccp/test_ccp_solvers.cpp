// The CCP solvers (APGD, projected Jacobi) on problems whose solution is known by hand: a
// resting sphere, a sliding one (the CCP's relaxed friction), a bilateral row, and a column of
// spheres each carrying those above it.
#include "sluice/ccp/ccp_solver.hpp"

#include <gtest/gtest.h>

#include "sluice/ccp/cone.hpp"
#include "sluice/ccp/row_group.hpp"

namespace sluice {
namespace {

constexpr Real kMass = 2.0, kStep = 1e-3, kGravity = 9.81;

// A contact of body b on the world's floor (normal +z), friction mu: its three rows.
void floor_contact(RowGroup& group, std::size_t b, Real least_normal_velocity, Real mu) {
  ConstraintRow n, u, v;
  n.b = u.b = v.b = b;
  n.linear_b = Vec3::UnitZ();
  u.linear_b = Vec3::UnitX();
  v.linear_b = Vec3::UnitY();
  n.bias = least_normal_velocity;
  group.add_cone(n, u, v, mu, 0);
}

class CcpSolvers : public ::testing::TestWithParam<std::string> {
 protected:
  CcpSettings settings() const {
    CcpSettings s;
    s.solver = GetParam();
    s.max_iterations = 2000;
    s.tolerance = 1e-10;
    return s;
  }
};

TEST_P(CcpSolvers, ARestingSphereTakesItsWeight) {
  CcpProblem p;
  p.bodies.add(Vec3(0, 0, -kGravity * kStep), Vec3::Zero(), 1 / kMass, 1.0, 0);
  RowGroup contacts;
  floor_contact(contacts, 0, 0, 0.5);
  p.add(contacts);
  BodyVelocities u;
  const CcpResult r = solve_ccp(p, settings(), u);
  EXPECT_LT(r.residual, 1e-10);
  // The residual stops at 1e-10 m/s: impulses within that times the mass.
  EXPECT_NEAR(contacts.rows()[0].impulse, kMass * kGravity * kStep, 1e-9);
  EXPECT_NEAR(u.linear[0].norm(), 0, 1e-10);
}

TEST_P(CcpSolvers, ASlidingSphereMeetsTheRelaxedCone) {
  // Anitescu & Tasora's cone complementarity: sliding at u_t > 0, the normal velocity after the
  // step is mu u_t (the relaxation), so gamma_n = m (mu v_t* - v_n*) / (1 + mu^2).
  const Real mu = 0.4, vt = 1.0, vn = -kGravity * kStep;
  CcpProblem p;
  p.bodies.add(Vec3(vt, 0, vn), Vec3::Zero(), 1 / kMass, 1.0, 0);
  RowGroup contacts;
  floor_contact(contacts, 0, 0, mu);
  p.add(contacts);
  BodyVelocities u;
  const CcpResult r = solve_ccp(p, settings(), u);
  EXPECT_LT(r.residual, 1e-10);
  const Real gamma_n = kMass * (mu * vt - vn) / (1 + mu * mu);
  EXPECT_NEAR(contacts.rows()[0].impulse, gamma_n, 1e-9);
  EXPECT_NEAR(contacts.rows()[1].impulse, -mu * gamma_n, 1e-9);
  EXPECT_NEAR(u.linear[0].x(), vt - mu * gamma_n / kMass, 1e-9);
  EXPECT_NEAR(u.linear[0].z(), mu * u.linear[0].x(), 1e-9);
}

TEST_P(CcpSolvers, ABilateralRowIsMetExactly) {
  CcpProblem p;
  p.bodies.add(Vec3(1, 2, 3), Vec3(0.5, 0, 0), 1 / kMass, Mat3::Identity() * 4, 0);
  RowGroup joints;
  ConstraintRow row;  // x velocity of the point (0, 0, 1) of the body to 0.25
  row.a = 0;
  row.linear_a = Vec3::UnitX();
  row.angular_a = Vec3(0, 0, 1).cross(Vec3::UnitX());
  row.bias = 0.25;
  joints.add_row(row);
  p.add(joints);
  BodyVelocities u;
  solve_ccp(p, settings(), u);
  EXPECT_NEAR(u.linear[0].x() + u.angular[0].cross(Vec3(0, 0, 1)).x(), 0.25, 1e-10);
}

// A column of n spheres, the lowest on the floor: contact k (under sphere k) carries the
// weight of the n - k spheres from k up, over the step.
CcpResult column(std::size_t n, const CcpSettings& s, std::vector<Real>& impulses) {
  CcpProblem p;
  RowGroup contacts;
  for (std::size_t k = 0; k < n; ++k) {
    p.bodies.add(Vec3(0, 0, -kGravity * kStep), Vec3::Zero(), 1 / kMass, 1.0, 0);
    ConstraintRow row;
    row.a = k == 0 ? ConstraintRow::kWorld : k - 1;
    row.b = k;
    row.linear_a = -Vec3::UnitZ();
    row.linear_b = Vec3::UnitZ();
    row.lower = 0;
    contacts.add_row(row);
  }
  p.add(contacts);
  BodyVelocities u;
  const CcpResult r = solve_ccp(p, s, u);
  impulses.clear();
  for (const ConstraintRow& row : contacts.rows()) impulses.push_back(row.impulse);
  return r;
}

TEST_P(CcpSolvers, AColumnCarriesTheSpheresAboveEachContact) {
  std::vector<Real> impulses;
  CcpSettings s = settings();
  s.max_iterations = 100000;
  s.tolerance = 1e-9;
  const CcpResult r = column(20, s, impulses);
  EXPECT_LT(r.residual, 1e-9);
  for (std::size_t k = 0; k < impulses.size(); ++k) {
    const Real expected = Real(20 - k) * kMass * kGravity * kStep;
    // The column's N is ill-conditioned (its eigenvalues span n^2): impulses to 1e-5.
    EXPECT_NEAR(impulses[k], expected, 1e-5 * expected) << k;
  }
}

INSTANTIATE_TEST_SUITE_P(, CcpSolvers, ::testing::Values("apgd", "jacobi"));

TEST(CcpSolverComparison, ApgdNeedsFewerIterationsThanJacobiOnAColumn) {
  std::vector<Real> impulses;
  CcpSettings s;
  s.max_iterations = 100000;
  s.tolerance = 1e-6;
  s.solver = "apgd";
  const int apgd = column(40, s, impulses).iterations;
  s.solver = "jacobi";
  const int jacobi = column(40, s, impulses).iterations;
  std::printf("column of 40: APGD %d iterations, projected Jacobi %d\n", apgd, jacobi);
  EXPECT_LT(5 * apgd, jacobi);
}

TEST(CcpSolverComparison, AnUnknownSolverIsAnError) {
  CcpProblem p;
  BodyVelocities u;
  CcpSettings s;
  s.solver = "newton";
  EXPECT_THROW(solve_ccp(p, s, u), std::invalid_argument);
}

// Rows on bodies (what joints and a monolithic fluid add): a unilateral row stops an approach
// and lets a separation go, an equality between two bodies keeps their momentum, a row at an
// offset point turns the body as well as moving it, and a row on a fixed body alone is
// dropped as inert.
CcpResult solve_rows(CcpProblem& p, RowGroup& rows, BodyVelocities& u) {
  rows.drop_inert(p.bodies);
  p.add(rows);
  CcpSettings s;
  s.tolerance = 1e-12;
  s.max_iterations = 1000;
  return solve_ccp(p, s, u);
}

ConstraintRow unilateral_up(std::size_t a) {
  ConstraintRow r;
  r.a = a;
  r.linear_a = Vec3::UnitZ();
  r.lower = 0;  // it may push up, never pull down
  return r;
}

TEST(CcpRows, UnilateralRowStopsAnApproachAndFreesASeparation) {
  for (const Real vz : {-0.5, 0.5}) {
    CcpProblem p;
    p.bodies.add(Vec3(0.3, 0, vz), Vec3::Zero(), 0.5, Mat3::Identity() * 5, 0);
    RowGroup rows;
    rows.add_row(unilateral_up(0));
    BodyVelocities u;
    solve_rows(p, rows, u);
    EXPECT_NEAR(u.linear[0].z(), std::max<Real>(vz, 0), 1e-12) << vz;
    EXPECT_NEAR(u.linear[0].x(), 0.3, 1e-15);  // frictionless: the tangential part is kept
    EXPECT_NEAR(rows.rows()[0].impulse, vz < 0 ? 1.0 : 0.0, 1e-12);  // m |v_n|
  }
}

TEST(CcpRows, EqualityBetweenTwoBodiesKeepsMomentum) {
  CcpProblem p;
  p.bodies.add(Vec3(1, 0, 0), Vec3::Zero(), 1.0, Mat3::Identity(), 0);
  p.bodies.add(Vec3(-1, 0, 0), Vec3::Zero(), 1 / 3.0, Mat3::Identity(), 0);
  RowGroup rows;
  ConstraintRow r;
  r.a = 0;
  r.b = 1;
  r.linear_a = Vec3::UnitX();
  r.linear_b = -Vec3::UnitX();  // v_a,x - v_b,x = 0
  rows.add_row(r);
  BodyVelocities u;
  solve_rows(p, rows, u);
  EXPECT_NEAR(u.linear[0].x(), -0.5, 1e-12);  // the common velocity
  EXPECT_NEAR(u.linear[1].x(), -0.5, 1e-12);
}

TEST(CcpRows, OffsetRowTurnsTheBodyAndFixedBodiesAreInert) {
  CcpProblem p;
  p.bodies.add(Vec3(0, 0, -1), Vec3::Zero(), 1.0, Mat3::Identity() * 10, 0);
  p.bodies.add(Vec3(0, 0, -1), Vec3::Zero(), 0, Mat3::Zero(), 0);  // fixed
  RowGroup rows;
  ConstraintRow r = unilateral_up(0);
  const Vec3 arm(0.1, 0, 0);
  r.angular_a = arm.cross(Vec3::UnitZ());
  rows.add_row(r);
  rows.add_row(unilateral_up(1));
  BodyVelocities u;
  solve_rows(p, rows, u);
  EXPECT_EQ(rows.size(), 1u);  // the fixed body's row is gone
  EXPECT_NEAR(u.linear[0].z() + u.angular[0].cross(arm).z(), 0, 1e-12);
  EXPECT_GT(u.linear[0].z(), -1);
  EXPECT_NE(u.angular[0].norm(), 0);
  EXPECT_EQ(u.linear[1].z(), -1);
}

// In a 2D case (the x-z plane) a row out of the plane moves nothing and is dropped.
TEST(CcpRows, RowsAlongLockedDirectionsAreInert) {
  CcpProblem p;
  p.bodies.add(Vec3::Zero(), Vec3::Zero(), 1.0, Mat3::Identity(), kLockPlanar);
  RowGroup rows;
  ConstraintRow along_y;
  along_y.a = 0;
  along_y.linear_a = Vec3::UnitY();
  rows.add_row(along_y);
  ConstraintRow about_x;
  about_x.a = 0;
  about_x.angular_a = Vec3::UnitX();
  rows.add_row(about_x);
  ConstraintRow along_x;
  along_x.a = 0;
  along_x.linear_a = Vec3::UnitX();
  rows.add_row(along_x);
  rows.drop_inert(p.bodies);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows.rows()[0].linear_a, Vec3::UnitX());
}

}  // namespace
}  // namespace sluice
