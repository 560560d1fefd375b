// A complementarity problem solved on the emulated device (ccp/device_ccp_problem.hpp): its
// bodies and groups copied there, the same solver steps run over the copies. It must give the
// host's solve to the bit: the impulses handed back to the groups, the bodies' velocities, the
// iterations and the residual, for both solvers, on a problem with a rigid body resting on a
// pile of frictional spheres with rolling resistance, held by a joint row.
#include "sluice/ccp/device_ccp_problem.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "sluice/ccp/ccp_solver.hpp"
#include "sluice/ccp/device_ccp_groups.hpp"
#include "sluice/exec/host_backend.hpp"

namespace sluice {
namespace {

constexpr Real kStep = 1e-3, kGravity = 9.81, kRadius = 0.01, kMass = 0.5;

// Bodies: a box (a full inverse inertia, 2 kg) and then n spheres in a zig-zag column under
// it, with each sphere touching the floor, the next sphere and, for the top one, the box.
struct Pile {
  CcpProblem problem;
  SphereContacts spheres;
  RowGroup rows;

  explicit Pile(std::size_t n, Real friction, Real rolling) {
    Mat3 inertia = Mat3::Identity() * 50;
    inertia(0, 1) = inertia(1, 0) = 3;  // not diagonal: the tensor path
    problem.bodies.add(Vec3(0.1, 0, -1), Vec3(0, 0.5, 0), 0.5, inertia, 0);
    for (std::size_t k = 0; k < n; ++k) {
      problem.bodies.add(Vec3(0.01 * Real(k % 3), 0, -kGravity * kStep), Vec3(0, 0.1 * Real(k), 0),
                         1 / kMass, 1 / (0.4 * kMass * kRadius * kRadius), 0);
    }
    spheres.begin(1, n, n, friction, 0, rolling);
    for (std::size_t k = 0; k < n; ++k) {
      SphereContact floor;  // every sphere on the floor, tilted a little each
      floor.a = kSphereWorld;
      floor.b = std::uint32_t(1 + k);
      floor.owner = std::uint32_t(k);
      floor.partner = SphereContacts::wall_code(0);
      floor.normal = Vec3(0.1 * Real(k % 2), 0, 1).normalized();
      floor.radius_b = kRadius;
      floor.target = k % 2 ? -0.001 : 0.0;
      spheres.contacts().push_back(floor);
      if (k + 1 == n) break;
      SphereContact c;
      c.a = std::uint32_t(2 + k);
      c.b = std::uint32_t(1 + k);
      c.owner = std::uint32_t(k);
      c.partner = std::uint32_t(k + 1);
      c.normal = Vec3(k % 2 ? 0.6 : -0.6, 0, -0.8);
      c.radius_a = c.radius_b = kRadius;
      spheres.contacts().push_back(c);
    }
    spheres.finish();
    // The box on the top sphere (a cone of rows) and pinned to the world along y (a joint row).
    ConstraintRow normal, u, v;
    normal.a = 0;
    normal.b = n;
    normal.linear_a = Vec3::UnitZ();
    normal.angular_a = Vec3(0, 0.05, 0);
    normal.linear_b = -Vec3::UnitZ();
    normal.lower = 0;
    u = normal;
    u.linear_a = Vec3::UnitX();
    u.linear_b = -Vec3::UnitX();
    v = normal;
    v.linear_a = Vec3::UnitY();
    v.linear_b = -Vec3::UnitY();
    rows.add_cone(normal, u, v, 0.5, 0);
    ConstraintRow pin;
    pin.a = 0;
    pin.linear_a = Vec3::UnitY();
    pin.angular_a = Vec3(0.1, 0, 0.2);
    rows.add_row(pin);
    problem.add(spheres);
    problem.add(rows);
  }
};

void expect_device_solve_is_the_hosts(Real friction, Real rolling, const std::string& solver) {
  CcpSettings settings;
  settings.solver = solver;
  settings.tolerance = 1e-10;
  settings.max_iterations = 300;
  Pile host(40, friction, rolling), device(40, friction, rolling);
  BodyVelocities u_host, u_device;
  const CcpResult a = solve_ccp(host.problem, settings, u_host);
  DeviceCcpProblem<exec::HostBackend> copy;
  add_ccp_group_copiers(copy);
  const CcpResult b = solve_ccp_on(copy, device.problem, settings, u_device);
  const std::string what = solver + ", friction " + std::to_string(friction);
  ASSERT_GT(a.iterations, 5) << what;
  EXPECT_EQ(b.iterations, a.iterations) << what;
  EXPECT_EQ(b.residual, a.residual) << what;
  EXPECT_EQ(u_device.linear, u_host.linear) << what;
  EXPECT_EQ(u_device.angular, u_host.angular) << what;
  std::vector<Real> gamma_host(host.problem.size()), gamma_device(device.problem.size());
  host.problem.warm_start(gamma_host);  // what the solve stored
  device.problem.warm_start(gamma_device);
  EXPECT_EQ(gamma_device, gamma_host) << what;
  // Not a trivial problem: most contacts push.
  const auto pushing =
      std::count_if(gamma_host.begin(), gamma_host.end(), [](Real g) { return g != 0; });
  EXPECT_GT(std::size_t(pushing), gamma_host.size() / 4) << what;
}

TEST(DeviceCcp, EmulatedSolveIsTheHostSolveBitForBit) {
  for (const std::string solver : {"apgd", "jacobi"}) {
    expect_device_solve_is_the_hosts(0, 0, solver);       // one row a contact
    expect_device_solve_is_the_hosts(0.4, 0, solver);     // cones
    expect_device_solve_is_the_hosts(0.4, 0.05, solver);  // cones and rolling resistance
  }
}

TEST(DeviceCcp, AGroupWithNoDeviceCopyIsAnError) {
  Pile pile(3, 0, 0);
  DeviceCcpProblem<exec::HostBackend> copy;  // no copiers
  BodyVelocities u;
  EXPECT_THROW(solve_ccp_on(copy, pile.problem, CcpSettings{}, u), std::logic_error);
}

}  // namespace
}  // namespace sluice
