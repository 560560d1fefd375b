// The contact law alone: Hertz impact of a sphere on a plane against the analytic contact time
// and peak overlap (C2 of VALIDATION.md), restitution reproduced (the law behind C1), and
// Coulomb stick and slip.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "sluice/contact/hertz_mindlin.hpp"
#include "sluice/rigid/rigid_integrator.hpp"

namespace sluice {
namespace {

struct Impact {
  double contact_time = 0;
  double peak_overlap = 0;
  double rebound_speed = 0;
};

// A sphere of radius R falls at speed v0 onto the plane z = 0 (no gravity during contact).
Impact drop_sphere(const ContactMaterial& material, double mass, double radius, double v0) {
  HertzDampingTable damping;
  const ContactPair pair = make_contact_pair(material, mass, radius, material, 0, 0, damping);
  RigidBody sphere;
  sphere.mass = mass;
  sphere.principal_inertia = Vec3::Constant(0.4 * mass * radius * radius);
  sphere.position = Vec3(0, 0, radius);
  sphere.velocity = Vec3(0, 0, -v0);
  const double t_hertz =
      2.868 *
      std::pow(mass * mass / (radius * pair.effective_young * pair.effective_young * v0), 0.2);
  const double dt = t_hertz / 2000;
  Vec3 tangential = Vec3::Zero();
  auto load = [&](const RigidBody& b, Vec3& f, Vec3& t) {
    const double overlap = radius - b.position[2];
    f.setZero();
    t.setZero();
    if (overlap > 0) {
      const Vec3 normal = Vec3::UnitZ();
      f = hertz_mindlin_force(pair, overlap, normal, b.velocity_at(b.position - radius * normal),
                              tangential, dt)
              .force;
    }
  };
  Vec3 force, torque;
  load(sphere, force, torque);
  Impact out;
  double time = 0;
  bool touched = false;
  while (time < 3 * t_hertz) {
    step_rigid(sphere, force, torque, dt, load);
    time += dt;
    const double overlap = radius - sphere.position[2];
    if (overlap > 0) {
      touched = true;
      out.contact_time += dt;
      out.peak_overlap = std::max(out.peak_overlap, overlap);
    } else if (touched && force.norm() == 0) {
      break;
    }
  }
  out.rebound_speed = sphere.velocity[2];
  return out;
}

TEST(HertzMindlin, ElasticImpactMatchesHertzTheory) {
  ContactMaterial steel{2e11, 0.3, 1.0, 0.0};
  const double radius = 0.01, v0 = 1.0;
  const double mass = 7800 * 4.0 / 3.0 * M_PI * std::pow(radius, 3);
  // Against a rigid plane the pair's E* comes from both materials (the plane is steel too).
  const double e_star = 1 / (2 * (1 - 0.09) / 2e11);
  const double t_c = 2.868 * std::pow(mass * mass / (radius * e_star * e_star * v0), 0.2);
  const double delta_max = std::pow(15 * mass * v0 * v0 / (16 * e_star * std::sqrt(radius)), 0.4);
  const Impact impact = drop_sphere(steel, mass, radius, v0);
  std::printf(
      "C2 Hertz impact: contact time %.4g s (theory %.4g), peak overlap %.4g m (theory %.4g)\n",
      impact.contact_time, t_c, impact.peak_overlap, delta_max);
  EXPECT_NEAR(impact.contact_time, t_c, 0.05 * t_c);
  EXPECT_NEAR(impact.peak_overlap, delta_max, 0.05 * delta_max);
  EXPECT_NEAR(impact.rebound_speed, v0, 1e-3 * v0);
}

class Restitution : public ::testing::TestWithParam<double> {};

TEST_P(Restitution, ReboundOverImpactSpeedIsE) {
  const double e = GetParam();
  const ContactMaterial material{1e8, 0.3, e, 0.0};
  for (double v0 : {0.5, 2.0}) {  // Hertz damping of this form makes e independent of speed
    const Impact impact = drop_sphere(material, 0.5, 0.05, v0);
    std::printf("C1 law: e = %.2f, v0 = %.1f m/s: rebound ratio %.5f\n", e, v0,
                impact.rebound_speed / v0);
    EXPECT_NEAR(impact.rebound_speed / v0, e, 0.03 * e) << "v0 = " << v0;
  }
}

INSTANTIATE_TEST_SUITE_P(C1, Restitution, ::testing::Values(0.2, 0.5, 0.9));

TEST(HertzMindlin, StaticFrictionHoldsAndSlidingForceIsMuTimesNormal) {
  const ContactMaterial material{1e8, 0.3, 0.5, 0.4};
  HertzDampingTable damping;
  const ContactPair pair = make_contact_pair(material, 1.0, 0.1, material, 0, 0, damping);
  const Vec3 normal = Vec3::UnitZ();
  const double overlap = 1e-4;
  // Sticking: a tiny tangential creep stays below mu F_n and the spring opposes it.
  Vec3 tangential = Vec3::Zero();
  ContactForce f = hertz_mindlin_force(pair, overlap, normal, Vec3(1e-4, 0, 0), tangential, 1e-4);
  EXPECT_FALSE(f.sliding);
  EXPECT_LT(f.force[0], 0);
  EXPECT_LT(std::abs(f.force[0]), pair.friction * f.normal);
  // Sliding: a steady slip saturates at mu |F_n|, opposite to the slip.
  for (int k = 0; k < 1000; ++k)
    f = hertz_mindlin_force(pair, overlap, normal, Vec3(0.5, 0, 0), tangential, 1e-4);
  EXPECT_TRUE(f.sliding);
  EXPECT_NEAR(f.force[0], -pair.friction * f.normal, 1e-9 * f.normal);
  EXPECT_NEAR(f.force[2], f.normal, 1e-12);
}

TEST(HertzMindlin, DampingForRestitutionIsMonotonic) {
  EXPECT_EQ(hertz_damping_for_restitution(1.0), 0.0);
  double previous = 0;
  for (double e : {0.95, 0.8, 0.5, 0.2, 0.05}) {
    const double gamma = hertz_damping_for_restitution(e);
    EXPECT_GT(gamma, previous) << e;
    previous = gamma;
  }
  EXPECT_THROW(hertz_damping_for_restitution(0.0), std::invalid_argument);
  EXPECT_THROW(hertz_damping_for_restitution(1.5), std::invalid_argument);
}

TEST(HertzMindlin, DampingTableRemembersTheBisection) {
  HertzDampingTable table;
  EXPECT_EQ(table.gamma(0.5), hertz_damping_for_restitution(0.5));
  EXPECT_EQ(table.gamma(0.5), table.gamma(0.5));
  EXPECT_GT(table.gamma(0.2), table.gamma(0.5));
  EXPECT_THROW(table.gamma(0.0), std::invalid_argument);
}

}  // namespace
}  // namespace sluice
