// The constraint fluid's rows (density and viscosity constraints): the Jacobian is the
// derivative of the constraints, the impulses act through its transpose, and the viscosity
// rows leave a uniform motion alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "sluice/fluid/constraint/constraint_model.hpp"
#include "sluice/sim/simulation.hpp"

namespace sluice {
namespace {

// The floating box case at a coarse spacing, its fluid shaken (so that no gradient vanishes by
// the lattice's symmetry) and sorted again.
struct ShakenBox {
  Simulation<2> sim;
  ConstraintModel<2>& model;
  std::mt19937 random{7};

  ShakenBox()
      : sim(io::read_case(std::string(SLUICE_SOURCE_DIR) + "/cases/floating_box_2d.yaml",
                          {"model.name=constraint", "spacing=0.1", "model.viscosity=0.01"})),
        model(dynamic_cast<ConstraintModel<2>&>(sim.fluid())) {
    auto& s = model.state();
    std::uniform_real_distribution<double> shake(-0.15, 0.15);
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      if (!s.particles.is_fluid(i)) continue;
      for (int a = 0; a < 2; ++a) s.particles.position[i][a] += 0.1 * shake(random);
    }
    std::vector<std::uint32_t> order;
    s.cells.sort(s.particles.position, order);
    s.particles.reorder(order);
    model.build_rows();
  }

  // Random velocities: the fluid particles' in the x-z plane, the box's along x and z and
  // about y (its degrees of freedom in 2D).
  BodyVelocities random_velocities() {
    std::normal_distribution<double> normal;
    const std::size_t fluid = model.rows().fluid_rows();
    BodyVelocities u;
    u.linear.assign(1 + fluid, Vec3::Zero());
    u.angular.assign(1 + fluid, Vec3::Zero());
    for (auto& v : u.linear) v = Vec3(normal(random), 0, normal(random));
    u.angular[0] = Vec3(0, normal(random), 0);
    return u;
  }

  std::vector<Real> constraint_values() const {
    std::vector<Real> c(model.rows().size());
    for (std::size_t r = 0; r < c.size(); ++r) c[r] = model.rows().constraint(r);
    return c;
  }

  // Moves the fluid particles by e u and the box's particles by e times its rigid motion.
  void move(const BodyVelocities& u, double e) {
    auto& ps = model.state().particles;
    const Vec3 centre = sim.bodies().state(0).position;
    for (std::size_t r = 0; r < model.rows().fluid_rows(); ++r) {
      ps.position[model.row_particle(r)] += e * from_3d<2>(u.linear[1 + r]);
    }
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (ps.body_point[i] < 0) continue;
      const Vec3 arm = to_3d<2>(ps.position[i]) - centre;
      ps.position[i] += e * from_3d<2>(u.linear[0] + u.angular[0].cross(arm));
    }
  }
};

// Each row's velocity J u is the rate of change of its constraint as the particles and the box
// move with u (central differences), within 1e-6 of the largest rate.
TEST(ConstraintRows, JacobianIsTheConstraintsDerivative) {
  ShakenBox box;
  DensityConstraints& rows = const_cast<DensityConstraints&>(box.model.rows());
  ASSERT_GT(rows.size(), rows.fluid_rows());  // wall and body rows too
  ASSERT_FALSE(rows.body_entries().empty());
  rows.place(1);
  const BodyVelocities u = box.random_velocities();
  std::fill(rows.target().begin(), rows.target().end(), 0.0);
  std::vector<Real> rate(rows.size());
  rows.row_velocities(u, rate);

  const double e = 1e-6;
  box.move(u, e);
  box.model.build_rows();
  const std::vector<Real> ahead = box.constraint_values();
  box.move(u, -2 * e);
  box.model.build_rows();
  const std::vector<Real> behind = box.constraint_values();
  ASSERT_EQ(ahead.size(), rate.size());
  double largest = 0, worst = 0;
  for (std::size_t r = 0; r < rate.size(); ++r) {
    largest = std::max(largest, std::abs(rate[r]));
    worst = std::max(worst, std::abs((ahead[r] - behind[r]) / (2 * e) - rate[r]));
  }
  EXPECT_GT(largest, 0.1);
  EXPECT_LT(worst, 1e-6 * largest);
}

// The impulses act through J^T: for any gamma and u, gamma . (J u) = u . (M du), du the
// velocity change apply_impulses gives (the box with unit mass and inertia), and the same for
// the viscosity rows.
template <class Rows>
void expect_transpose(ShakenBox& box, const Rows& rows, Real particle_mass) {
  const BodyVelocities u = box.random_velocities();
  std::vector<Real> gamma(rows.size()), rate(rows.size());
  std::normal_distribution<double> normal;
  for (auto& g : gamma) g = normal(box.random);
  CcpBodies bodies;
  bodies.add(Vec3::Zero(), Vec3::Zero(), 1.0, Mat3::Identity(), kLockPlanar);
  for (std::size_t r = 0; r < u.linear.size() - 1; ++r)
    bodies.add(Vec3::Zero(), Vec3::Zero(), 1 / particle_mass, 0.0, kLockPlanar);
  BodyVelocities du;
  du.linear.assign(u.linear.size(), Vec3::Zero());
  du.angular.assign(u.linear.size(), Vec3::Zero());
  rows.apply_impulses(bodies, gamma, du);
  rows.row_velocities(u, rate);
  double left = 0, right = du.linear[0].dot(u.linear[0]) + du.angular[0].dot(u.angular[0]);
  for (std::size_t r = 0; r < rows.size(); ++r) left += gamma[r] * rate[r];
  for (std::size_t k = 1; k < u.linear.size(); ++k)
    right += particle_mass * du.linear[k].dot(u.linear[k]);
  EXPECT_NEAR(left, right, 1e-12 * std::max(1.0, std::abs(left)));
}

TEST(ConstraintRows, ImpulsesActThroughTheTranspose) {
  ShakenBox box;
  const Real mass = 1000 * 0.1 * 0.1;
  auto& rows = const_cast<DensityConstraints&>(box.model.rows());
  rows.place(1);
  std::fill(rows.target().begin(), rows.target().end(), 0.0);
  expect_transpose(box, rows, mass);
  auto& viscous = const_cast<ViscosityConstraints&>(box.model.viscosity_rows());
  viscous.place(1);
  expect_transpose(box, viscous, mass);
}

// Of the box's particles only its outer layer (half a spacing deep) gets density rows, though
// its second layer has fluid within the kernel's support too (density_row_build.hpp,
// NearFluid).
TEST(ConstraintRows, OnlyABodysOuterLayerHasRows) {
  ShakenBox box;
  const auto& ps = box.model.state().particles;
  const Vec3 centre = box.sim.bodies().state(0).position;
  const Vec3 half = 0.5 * box.sim.config().bodies.front().size;
  const Real dx = 0.1, support = 2 * 1.3 * dx;  // the model's default h = 1.3 dx
  // A box particle's depth below the box's faces (x and z in 2D).
  auto depth = [&](std::size_t i) {
    const Vec3 p = to_3d<2>(ps.position[i]) - centre;
    return std::min(half.x() - std::abs(p.x()), half.z() - std::abs(p.z()));
  };
  std::vector<char> has_row(ps.size(), 0);
  for (std::size_t r = 0; r < box.model.rows().size(); ++r) has_row[box.model.row_particle(r)] = 1;
  int outer_rows = 0, deeper_near_fluid = 0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (ps.body_point[i] < 0) continue;
    const bool outer = depth(i) < dx;
    if (has_row[i]) {
      EXPECT_TRUE(outer) << "body particle " << i << " at depth " << depth(i) << " m has a row";
      outer_rows += outer;
    }
    bool near = false;
    for (std::size_t j = 0; j < ps.size(); ++j) {
      near = near || (ps.is_fluid(j) && (ps.position[j] - ps.position[i]).norm() < support);
    }
    deeper_near_fluid += !outer && near;
  }
  EXPECT_GT(outer_rows, 0);
  EXPECT_GT(deeper_near_fluid, 0);  // the rule left some out
}

// A uniform motion has no velocity relative to the neighbours' mean: the viscosity rows read
// zero for it.
TEST(ConstraintRows, ViscosityRowsLeaveAUniformMotionAlone) {
  ShakenBox box;
  auto& viscous = const_cast<ViscosityConstraints&>(box.model.viscosity_rows());
  viscous.place(1);
  BodyVelocities u = box.random_velocities();
  for (std::size_t k = 1; k < u.linear.size(); ++k) u.linear[k] = Vec3(0.3, 0, -1.2);
  std::vector<Real> rate(viscous.size());
  viscous.row_velocities(u, rate);
  for (const Real v : rate) EXPECT_NEAR(v, 0, 1e-12);
}

// SPOOK's coefficients (Lacoursiere 2007): Upsilon = 1 / (1 + 4 d), the violation's rate
// 4 Upsilon / h, the compliance factor 4 / (h^2 (1 + 4 d)).
TEST(ConstraintRows, SpookCoefficients) {
  const SpookStep spook(0.01, 3);
  EXPECT_DOUBLE_EQ(spook.velocity_share, 1.0 / 13);
  EXPECT_DOUBLE_EQ(spook.violation_rate, 4.0 / (0.01 * 13));
  EXPECT_DOUBLE_EQ(spook.compliance, 4.0 / (1e-4 * 13));
  EXPECT_DOUBLE_EQ(spook.target(0.002, 0.5), -4.0 / (0.01 * 13) * 0.002 + 0.5 / 13);
}

}  // namespace
}  // namespace sluice
