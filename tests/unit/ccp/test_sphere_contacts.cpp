// The compact group of a granular fluid's sphere contacts (ccp/sphere_contacts.hpp): a column
// of spheres on a wall carries the spheres above each contact, friction holds a sphere on a
// slope the way RowGroup's cone does, and the impulses carry over to the next step by the
// spheres' identities.
#include "sluice/ccp/sphere_contacts.hpp"

#include <gtest/gtest.h>

#include "sluice/ccp/ccp_solver.hpp"

namespace sluice {
namespace {

constexpr Real kMass = 0.5, kStep = 1e-3, kGravity = 9.81, kRadius = 0.01;

// A column of n spheres on the floor (a wall), identities in reverse order of height so that
// contacts point from the upper sphere (smaller identity) down.
void column(CcpProblem& p, SphereContacts& group, std::size_t n) {
  p.bodies.clear();
  for (std::size_t k = 0; k < n; ++k) {
    p.bodies.add(Vec3(0, 0, -kGravity * kStep), Vec3::Zero(), 1 / kMass,
                 1 / (0.4 * kMass * kRadius * kRadius), 0);
  }
  group.begin(0, n, n, 0, 0);
  SphereContacts::Contact floor;
  floor.a = SphereContacts::kWorld;
  floor.b = 0;
  floor.owner = std::uint32_t(n - 1);
  floor.partner = SphereContacts::wall_code(0);
  floor.normal = Vec3::UnitZ();
  floor.radius_b = kRadius;
  group.contacts().push_back(floor);
  for (std::size_t k = 1; k < n; ++k) {
    SphereContacts::Contact c;  // from sphere k (upper, identity n - 1 - k) down into k - 1
    c.a = std::uint32_t(k);
    c.b = std::uint32_t(k - 1);
    c.owner = std::uint32_t(n - 1 - k);
    c.partner = std::uint32_t(n - k);
    c.normal = -Vec3::UnitZ();
    c.radius_a = c.radius_b = kRadius;
    group.contacts().push_back(c);
  }
  group.finish();
  p.clear_groups();
  p.add(group);
}

TEST(SphereContacts, AColumnCarriesTheSpheresAboveAndWarmStartsTheNextStep) {
  CcpProblem p;
  SphereContacts group;
  column(p, group, 10);
  CcpSettings s;
  s.tolerance = 1e-9;
  s.max_iterations = 10000;
  BodyVelocities u;
  const CcpResult first = solve_ccp(p, s, u);
  EXPECT_LT(first.residual, 1e-9);
  for (std::size_t c = 0; c < 10; ++c) {
    const Real expected = Real(10 - c) * kMass * kGravity * kStep;  // contact c is under sphere c
    EXPECT_NEAR(group.normal_impulse(c), expected, 1e-6 * expected) << c;
  }
  for (std::size_t k = 0; k < 10; ++k) EXPECT_NEAR(u.linear[k].z(), 0, 1e-8);
  // The same contacts next step: they start from the last impulses, already a solution.
  column(p, group, 10);
  std::vector<Real> start(group.size());
  group.warm_start(start);
  EXPECT_NEAR(start[0], 10 * kMass * kGravity * kStep, 1e-6 * 10 * kMass * kGravity * kStep);
  const CcpResult second = solve_ccp(p, s, u);
  std::printf("column of 10 spheres: %d iterations cold, %d warm\n", first.iterations,
              second.iterations);
  EXPECT_LE(second.iterations, 2);
}

TEST(SphereContacts, FrictionStopsASlidingSphereAsTheRowCone) {
  // One sphere sliding on a wall at 1 m/s with mu = 0.4: the relaxed cone's answer, as in
  // CcpSolvers.ASlidingSphereMeetsTheRelaxedCone (no spin: the contact's torque turns it, so
  // the slip is that of the contact point).
  CcpProblem p;
  SphereContacts group;
  p.bodies.add(Vec3(1, 0, -kGravity * kStep), Vec3::Zero(), 1 / kMass,
               1 / (0.4 * kMass * kRadius * kRadius), 0);
  group.begin(0, 1, 1, 0.4, 0);
  SphereContacts::Contact c;
  c.a = SphereContacts::kWorld;
  c.b = 0;
  c.partner = SphereContacts::wall_code(0);
  c.normal = Vec3::UnitZ();
  c.radius_b = kRadius;
  group.contacts().push_back(c);
  group.finish();
  p.add(group);
  CcpSettings s;
  s.tolerance = 1e-10;
  s.max_iterations = 10000;
  BodyVelocities u;
  solve_ccp(p, s, u);
  // The contact point slips at u_x - r w_y (w picked up from the friction's torque); the
  // cone holds, |gamma_t| = mu gamma_n, while it slips, and the relaxation lifts it by mu |slip|.
  std::vector<Real> gamma(group.size());
  group.warm_start(gamma);
  EXPECT_GT(gamma[0], 0);
  EXPECT_NEAR(std::hypot(gamma[1], gamma[2]), 0.4 * gamma[0], 1e-9);
  const Real slip = u.linear[0].x() - kRadius * u.angular[0].y();  // v + w x (-r n), x part
  EXPECT_GT(slip, 0);
  EXPECT_NEAR(u.linear[0].z(), 0.4 * std::abs(slip), 1e-8);  // the relaxation's lift
}

}  // namespace
}  // namespace sluice
