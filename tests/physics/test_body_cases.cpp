// The rigid-body checks of VALIDATION.md run from the shipped case files (cases/), in process:
// C1, C3, C4, C5 and C7 without fluid, B1 and B3 with it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "physics_support.hpp"

namespace sluice {
namespace {

using testing::load_case;
using testing::run_until;

double rotation_degrees(const Eigen::Quaterniond& q) {
  return 2 * std::atan2(q.vec().norm(), std::abs(q.w())) * 180 / std::numbers::pi;
}

// C1: rebound / impact normal speed, each taken at the step the contact starts and ends.
class CaseDropAndBounce : public ::testing::TestWithParam<double> {};

TEST_P(CaseDropAndBounce, ReboundRatioIsRestitution) {
  const double e = GetParam();
  const std::string r = std::to_string(e);
  Simulation<3> sim(load_case("drop_bounce.yaml", {"bodies.0.material.restitution=" + r,
                                                   "bodies.1.material.restitution=" + r}));
  const auto& bodies = sim.bodies();
  std::vector<double> impact(2, 0), rebound(2, 0), previous(2, 0);
  std::vector<bool> touched(2, false), done(2, false);
  run_until(sim, sim.config().end_time, [&](const SimulationState<3>&) {
    for (std::size_t b = 0; b < 2; ++b) {
      const bool touching = bodies.system().contact_force()[b].norm() > 0;
      if (touching && !touched[b]) impact[b] = -previous[b];
      if (touched[b] && !touching && !done[b]) {
        rebound[b] = bodies.state(b).velocity[2];
        done[b] = true;
      }
      touched[b] = touched[b] || touching;
      previous[b] = bodies.state(b).velocity[2];
    }
  });
  std::printf("C1 (case): e = %.2f: sphere %.4f (impact %.4f m/s), cube %.4f\n", e,
              rebound[0] / impact[0], impact[0], rebound[1] / impact[1]);
  for (std::size_t b = 0; b < 2; ++b) {
    ASSERT_TRUE(done[b]) << bodies.config(b).name << " did not bounce";
    EXPECT_NEAR(rebound[b] / impact[b], e, 0.03 * e) << bodies.config(b).name;
  }
}

INSTANTIATE_TEST_SUITE_P(C1, CaseDropAndBounce, ::testing::Values(0.2, 0.5, 0.9));

// C3: the block slides with a = g (sin theta - mu cos theta), or holds when tan theta < mu.
TEST(CaseIncline, SlidesWithTheCoulombAcceleration) {
  Simulation<3> sim(load_case("incline_block.yaml"));
  const double x0 = sim.bodies().state(0).position[0];
  run_until(sim, sim.config().end_time, [](const SimulationState<3>&) {});
  const double theta = 30 * std::numbers::pi / 180, mu = 0.3, t = sim.config().end_time;
  const double expected = 0.5 * 9.81 * (std::sin(theta) - mu * std::cos(theta)) * t * t;
  const double travelled = sim.bodies().state(0).position[0] - x0;
  std::printf("C3 (case): slid %.5f m in %.2f s, analytic %.5f m (%.2f %%)\n", travelled, t,
              expected, 100 * (travelled - expected) / expected);
  EXPECT_NEAR(travelled, expected, 0.02 * expected);
}

TEST(CaseIncline, HoldsWhenFrictionIsEnough) {
  // 20 degrees (tan = 0.36) with mu = 0.5.
  const double theta = 20 * std::numbers::pi / 180;
  const std::string g = "gravity=[" + std::to_string(9.81 * std::sin(theta)) + ", 0, " +
                        std::to_string(-9.81 * std::cos(theta)) + "]";
  Simulation<3> sim(
      load_case("incline_block.yaml", {g, "bodies.0.material.friction=0.5", "end_time=2.0"}));
  const Vec3 start = sim.bodies().state(0).position;
  run_until(sim, 2.0, [](const SimulationState<3>&) {});
  const double creep = (sim.bodies().state(0).position - start).head<2>().norm();
  std::printf("C3 (case): creep %.3g mm in 2 s\n", 1e3 * creep);
  EXPECT_LT(creep, 1e-3);
}

// C4: a cube on its face and a stack of three stay put for 5 s.
TEST(CaseRestingCubes, StayPutForFiveSeconds) {
  Simulation<3> sim(load_case("resting_cubes.yaml"));
  const auto& bodies = sim.bodies();
  std::vector<Vec3> start;
  for (std::size_t b = 0; b < bodies.count(); ++b) start.push_back(bodies.state(b).position);
  run_until(sim, sim.config().end_time, [](const SimulationState<3>&) {});
  for (std::size_t b = 0; b < bodies.count(); ++b) {
    const auto& s = bodies.state(b);
    const double drift = (s.position - start[b]).norm();
    const double angle = rotation_degrees(s.orientation);
    std::printf("C4 (case): %-12s drift %.3g mm, rotation %.3g deg\n",
                bodies.config(b).name.c_str(), 1e3 * drift, angle);
    EXPECT_LT(drift, 1e-3) << bodies.config(b).name;
    EXPECT_LT(angle, 0.1) << bodies.config(b).name;
  }
}

// C5: elastic, frictionless spheres in a closed box without gravity: the total energy stays
// within 1 % over at least 100 collisions. A collision is counted from the contact force of the
// bodies: each body's contact starts count, so a sphere-sphere collision counts twice and the
// test asks for 200 starts.
TEST(CaseElasticBox, EnergyKeptOverHundredCollisions) {
  Simulation<3> sim(load_case("elastic_box.yaml"));
  const auto& bodies = sim.bodies();
  const double start = bodies.system().energy().total();
  std::vector<bool> touching(bodies.count(), false);
  int starts = 0;
  double worst = 0;
  run_until(sim, sim.config().end_time, [&](const SimulationState<3>&) {
    for (std::size_t b = 0; b < bodies.count(); ++b) {
      const bool now = bodies.system().contact_force()[b].norm() > 0;
      if (now && !touching[b]) ++starts;
      touching[b] = now;
    }
    worst = std::max(worst, std::abs(bodies.system().energy().total() - start) / start);
  });
  std::printf("C5 (case): %d contact starts, largest energy change %.3g %%\n", starts, 100 * worst);
  EXPECT_GE(starts, 200);
  EXPECT_LT(worst, 0.01);
}

// C7: three squares in a row (2D): momentum kept to 1e-9, final velocities as the rigid-body
// collision sequence.
TEST(CaseThreeBodies, MomentumAndFinalVelocities) {
  Simulation<2> sim(load_case("three_body_2d.yaml"));
  const auto& bodies = sim.bodies();
  auto momentum = [&] {
    Vec3 p = Vec3::Zero();
    for (std::size_t b = 0; b < 3; ++b) p += bodies.state(b).mass * bodies.state(b).velocity;
    return p;
  };
  const Vec3 p0 = momentum();
  const double scale = 1.5 * 1.0 + 3.0 * 0.5;
  double worst = 0;
  run_until(sim, sim.config().end_time, [&](const SimulationState<2>&) {
    worst = std::max(worst, (momentum() - p0).norm() / scale);
  });
  const double expected[3] = {-1.0, 1.8 * 0.5 / 4.2, 3.0 / 4.2};
  std::printf("C7 (case): momentum error %.2g, velocities %.4f %.4f %.4f\n", worst,
              bodies.state(0).velocity[0], bodies.state(1).velocity[0],
              bodies.state(2).velocity[0]);
  EXPECT_LT(worst, 1e-9);
  for (std::size_t b = 0; b < 3; ++b) {
    EXPECT_NEAR(bodies.state(b).velocity[0], expected[b], 0.02) << bodies.config(b).name;
  }
}

}  // namespace
}  // namespace sluice
