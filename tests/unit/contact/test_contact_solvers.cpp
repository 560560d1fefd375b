#include "sluice/contact/contact_solvers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "sluice/contact/complementarity_contact_solver.hpp"

namespace sluice {
namespace {

TEST(ContactSolvers, BothMethodsAreSolversOfTheRegistry) {
  const ContactSolverRegistry registry = shipped_contact_solvers();
  EXPECT_EQ(registry.names(), (std::vector<std::string>{"complementarity", "penalty"}));
  EXPECT_FALSE(registry.make("penalty", {})->in_velocity_step());
  EXPECT_TRUE(registry.make("complementarity", {})->in_velocity_step());
  EXPECT_THROW(registry.make("lagrange", {}), std::invalid_argument);
}

// Two bodies touching at two particle pairs, one overlapping and one with a gap.
struct TwoBodies {
  std::vector<SystemBody> bodies = std::vector<SystemBody>(2);
  std::vector<ContactShape> shapes = std::vector<ContactShape>(2);
  ContactSet contacts;
  TwoBodies() {
    bodies[1].state.position = Vec3(0, 0, 1);
    shapes[0].material.friction = 0.6;
    shapes[1].material.friction = 0.3;
    contacts.begin_pass();
    contacts.add(0, 1, {Vec3(0.1, 0, 0.5), Vec3::UnitZ(), 2e-3, 1e-4});
    contacts.add(0, 1, {Vec3(-0.1, 0, 0.5), Vec3::UnitZ(), -1e-3, 1e-4});
    contacts.end_pass();
  }
};

TEST(ComplementarityContactSolver, EachPairIsAConeWithTheSmallerFrictionAndItsGapOverTheStep) {
  TwoBodies two;
  ComplementarityContactSolver solver;
  RowGroup rows;
  const double h = 0.01, recovery = 0.1;
  solver.add_cones(two.contacts, two.bodies, two.shapes, h, recovery, rows);
  ASSERT_EQ(rows.size(), 6u);
  ASSERT_EQ(rows.cones().size(), 2u);
  // The overlap is taken back at the recovery speed at most; the gap may close in the step.
  EXPECT_DOUBLE_EQ(rows.rows()[0].bias, recovery);
  EXPECT_DOUBLE_EQ(rows.rows()[3].bias, -1e-3 / h);
  // The normal row pushes body b along +z and body a along -z, about each centre of mass.
  EXPECT_EQ(rows.rows()[0].linear_b, Vec3::UnitZ());
  EXPECT_EQ(rows.rows()[0].linear_a, -Vec3::UnitZ());
  EXPECT_TRUE(rows.rows()[0].angular_b.isApprox(Vec3(0.1, 0, -0.5).cross(Vec3::UnitZ())));
  EXPECT_EQ(rows.rows()[0].a, 0u);
  EXPECT_EQ(rows.rows()[0].b, 1u);
  // Friction 0.3, the smaller: a tangential impulse of 0.45 per unit normal one lies outside
  // that cone (and inside 0.6's), so the projection changes it.
  std::vector<Real> gamma = {1, 0.45, 0, 1, 0.25, 0};
  rows.project(gamma);
  EXPECT_LT(std::hypot(gamma[1], gamma[2]), 0.3 * gamma[0] + 1e-12);
  EXPECT_LT(gamma[1], 0.45);
  EXPECT_EQ(gamma[3], 1);  // 0.25 lies inside
  EXPECT_EQ(gamma[4], 0.25);
}

TEST(ComplementarityContactSolver, ALastingContactStartsFromItsLastImpulses) {
  TwoBodies two;
  ComplementarityContactSolver solver;
  RowGroup rows;
  solver.add_cones(two.contacts, two.bodies, two.shapes, 0.01, 0.1, rows);
  for (std::size_t r = 0; r < rows.size(); ++r) rows.rows()[r].impulse = 1.0 + double(r);
  solver.remember_impulses(rows);
  // The same contact in the next pass: its pairs start where they ended.
  two.contacts.begin_pass();
  two.contacts.add(0, 1, {Vec3(0.1, 0, 0.5), Vec3::UnitZ(), 1e-3, 1e-4});
  two.contacts.add(0, 1, {Vec3(-0.1, 0, 0.5), Vec3::UnitZ(), 1e-3, 1e-4});
  two.contacts.end_pass();
  RowGroup next;
  solver.add_cones(two.contacts, two.bodies, two.shapes, 0.01, 0.1, next);
  ASSERT_EQ(next.size(), 6u);
  for (std::size_t r = 0; r < next.size(); ++r) EXPECT_EQ(next.rows()[r].impulse, 1.0 + double(r));
  // A new contact (against another face: another identity) starts from nothing.
  solver.remember_impulses(next);
  two.contacts.begin_pass();
  two.contacts.add(0, 1, {Vec3::Zero(), Vec3::UnitX(), 1e-3, 1e-4});
  two.contacts.end_pass();
  RowGroup fresh;
  solver.add_cones(two.contacts, two.bodies, two.shapes, 0.01, 0.1, fresh);
  ASSERT_EQ(fresh.size(), 3u);
  for (const ConstraintRow& row : fresh.rows()) EXPECT_EQ(row.impulse, 0.0);
}

}  // namespace
}  // namespace sluice
