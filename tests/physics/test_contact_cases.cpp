// The rigid-body contact checks of VALIDATION.md without fluid, run from the shipped case
// files (cases/), in process: C1, C3, C4, C5, C7, and a ball rolling down a plane wall.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "physics_support.hpp"
#include "reported_figure.hpp"

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
  run_until(sim, sim.config().end_time, [&](const StepClock&) {
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
    testing::expect_figure(
        {fmt::format("C1 rebound ratio against e = {}, {}", e, bodies.config(b).name), "%", 2},
        100 * (rebound[b] / impact[b] / e - 1), testing::Bound::within, 3);
  }
}

INSTANTIATE_TEST_SUITE_P(C1, CaseDropAndBounce, ::testing::Values(0.2, 0.5, 0.9));

// A ball on a plane wall sloping at 30 degrees. With mu = 0.5 (>= 2/7 tan 30) a solid sphere
// rolls without slipping: its centre accelerates at 5/7 g sin 30 and omega R = v. With mu = 0.1
// it slips: the centre at g (sin 30 - mu cos 30), the spin at 5/2 mu g cos 30 / R. Bars 0.5 %
// (sampling the ball's surface, not the physics, once made it roll 2 % slow).
struct SlopeRun {
  double distance = 0, speed = 0, spin = 0;  // along the slope, and about y
};

SlopeRun roll_down_the_slope(const std::vector<std::string>& overrides) {
  Simulation<3> sim(load_case("slope_roll.yaml", overrides));
  const Vec3 start = sim.bodies().state(0).position;
  run_until(sim, sim.config().end_time, [](const StepClock&) {});
  const double theta = 30 * std::numbers::pi / 180;
  const Vec3 down_slope(std::cos(theta), 0, -std::sin(theta));
  const RigidBody& ball = sim.bodies().state(0);
  return {(ball.position - start).dot(down_slope), ball.velocity.dot(down_slope),
          ball.angular_velocity()[1]};
}

TEST(CaseSlopeRoll, RollsWithoutSlipping) {
  const SlopeRun run = roll_down_the_slope({});
  const double theta = 30 * std::numbers::pi / 180, t = 0.5, radius = 0.05;
  const double a = 5.0 / 7.0 * 9.81 * std::sin(theta);
  std::printf("slope roll: %.5f m (analytic %.5f), v %.4f (%.4f), omega R %.4f\n", run.distance,
              0.5 * a * t * t, run.speed, a * t, run.spin * radius);
  using testing::Bound;
  testing::expect_figure({"slope roll distance against the analytic", "%", 3},
                         100 * (run.distance / (0.5 * a * t * t) - 1), Bound::within, 0.5);
  testing::expect_figure({"slope roll speed against the analytic", "%", 3},
                         100 * (run.speed / (a * t) - 1), Bound::within, 0.5);
  testing::expect_figure({"slope roll, omega R against the speed", "%", 3},
                         100 * (run.spin * radius / run.speed - 1), Bound::within, 0.5);
}

TEST(CaseSlopeRoll, SlipsWhenFrictionIsLow) {
  const double mu = 0.1;
  const SlopeRun run = roll_down_the_slope({"bodies.0.material.friction=0.1"});
  const double theta = 30 * std::numbers::pi / 180, t = 0.5, radius = 0.05;
  const double a = 9.81 * (std::sin(theta) - mu * std::cos(theta));
  const double alpha = 2.5 * mu * 9.81 * std::cos(theta) / radius;
  std::printf("slope slip: %.5f m (analytic %.5f), omega %.4f (%.4f)\n", run.distance,
              0.5 * a * t * t, run.spin, alpha * t);
  using testing::Bound;
  testing::expect_figure({"slope slip distance against the analytic", "%", 3},
                         100 * (run.distance / (0.5 * a * t * t) - 1), Bound::within, 0.5);
  testing::expect_figure({"slope slip spin against the analytic", "%", 3},
                         100 * (run.spin / (alpha * t) - 1), Bound::within, 0.5);
}

// C3: the block slides with a = g (sin theta - mu cos theta), or holds when tan theta < mu.
// While it slides, the floor's force on it must stay near its weight (within 20 %, after the
// first 50 ms of settling): seed 000's aim is contact without the jitter of sampled surfaces.
TEST(CaseIncline, SlidesWithTheCoulombAcceleration) {
  Simulation<3> sim(load_case("incline_block.yaml"));
  const double x0 = sim.bodies().state(0).position[0];
  const double weight = sim.bodies().state(0).mass * -sim.config().gravity[2];
  double lowest = 1e300, highest = 0;
  run_until(sim, sim.config().end_time, [&](const StepClock& s) {
    if (s.time < 0.05) return;
    const double normal = sim.bodies().system().contact_force()[0][2] / weight;
    lowest = std::min(lowest, normal);
    highest = std::max(highest, normal);
  });
  const double theta = 30 * std::numbers::pi / 180, mu = 0.3, t = sim.config().end_time;
  const double expected = 0.5 * 9.81 * (std::sin(theta) - mu * std::cos(theta)) * t * t;
  const double travelled = sim.bodies().state(0).position[0] - x0;
  std::printf(
      "C3 (case): slid %.5f m in %.2f s, analytic %.5f m (%.2f %%); normal force %.3f "
      "to %.3f times the weight\n",
      travelled, t, expected, 100 * (travelled - expected) / expected, lowest, highest);
  using testing::Bound;
  testing::expect_figure({"C3 slide against the analytic", "%", 2},
                         100 * (travelled / expected - 1), Bound::within, 2);
  testing::expect_figure({"C3 normal force / weight, the least", "", 3}, lowest, Bound::above, 0.8);
  testing::expect_figure({"C3 normal force / weight, the most", "", 3}, highest, Bound::below, 1.2);
}

TEST(CaseIncline, HoldsWhenFrictionIsEnough) {
  // 20 degrees (tan = 0.36) with mu = 0.5.
  const double theta = 20 * std::numbers::pi / 180;
  const std::string g = "gravity=[" + std::to_string(9.81 * std::sin(theta)) + ", 0, " +
                        std::to_string(-9.81 * std::cos(theta)) + "]";
  Simulation<3> sim(
      load_case("incline_block.yaml", {g, "bodies.0.material.friction=0.5", "end_time=2.0"}));
  const Vec3 start = sim.bodies().state(0).position;
  run_until(sim, 2.0, [](const StepClock&) {});
  const double creep = (sim.bodies().state(0).position - start).head<2>().norm();
  std::printf("C3 (case): creep %.3g mm in 2 s\n", 1e3 * creep);
  testing::expect_figure({"C3 creep when friction holds", "mm", 4}, 1e3 * creep,
                         testing::Bound::below, 1);
}

// C4: a cube on its face and a stack of three stay put for 5 s.
TEST(CaseRestingCubes, StayPutForFiveSeconds) {
  Simulation<3> sim(load_case("resting_cubes.yaml"));
  const auto& bodies = sim.bodies();
  std::vector<Vec3> start;
  for (std::size_t b = 0; b < bodies.count(); ++b) start.push_back(bodies.state(b).position);
  run_until(sim, sim.config().end_time, [](const StepClock&) {});
  for (std::size_t b = 0; b < bodies.count(); ++b) {
    const auto& s = bodies.state(b);
    const double drift = (s.position - start[b]).norm();
    const double angle = rotation_degrees(s.orientation);
    std::printf("C4 (case): %-12s drift %.3g mm, rotation %.3g deg\n",
                bodies.config(b).name.c_str(), 1e3 * drift, angle);
    testing::expect_figure({"C4 drift, " + bodies.config(b).name, "mm", 4}, 1e3 * drift,
                           testing::Bound::below, 1);
    testing::expect_figure({"C4 rotation, " + bodies.config(b).name, "deg", 4}, angle,
                           testing::Bound::below, 0.1);
  }
}

// C5: elastic, frictionless spheres in a closed box without gravity: the total energy stays
// within 1 % over at least 100 collisions. A collision is counted from the contact force of the
// bodies: each body's contact starts count, so a sphere-sphere collision counts twice and the
// test asks for 200 starts. It runs for twice the case's end time: over the case's own, the
// count (211 and 218 in the release and baseline builds) lay 1.6 of its spread between builds
// above 200.
TEST(CaseElasticBox, EnergyKeptOverHundredCollisions) {
  Simulation<3> sim(load_case("elastic_box.yaml"));
  const auto& bodies = sim.bodies();
  const double start = bodies.system().energy().total();
  std::vector<bool> touching(bodies.count(), false);
  int starts = 0;
  double worst = 0;
  run_until(sim, 2 * sim.config().end_time, [&](const StepClock&) {
    for (std::size_t b = 0; b < bodies.count(); ++b) {
      const bool now = bodies.system().contact_force()[b].norm() > 0;
      if (now && !touching[b]) ++starts;
      touching[b] = now;
    }
    worst = std::max(worst, std::abs(bodies.system().energy().total() - start) / start);
  });
  std::printf("C5 (case): %d contact starts, largest energy change %.3g %%\n", starts, 100 * worst);
  // A precondition (enough impacts for the energy check to mean something): at least 200.
  testing::expect_figure({"C5 contact starts", "", 0}, starts, testing::Bound::above, 200);
  testing::expect_figure({"C5 largest energy change", "%", 3}, 100 * worst, testing::Bound::below,
                         1);
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
  run_until(sim, sim.config().end_time,
            [&](const StepClock&) { worst = std::max(worst, (momentum() - p0).norm() / scale); });
  const double expected[3] = {-1.0, 1.8 * 0.5 / 4.2, 3.0 / 4.2};
  std::printf("C7 (case): momentum error %.2g, velocities %.4f %.4f %.4f\n", worst,
              bodies.state(0).velocity[0], bodies.state(1).velocity[0],
              bodies.state(2).velocity[0]);
  testing::expect_figure({"C7 momentum error", "", -1}, worst, testing::Bound::below, 1e-9);
  for (std::size_t b = 0; b < 3; ++b) {
    EXPECT_NEAR(bodies.state(b).velocity[0], expected[b], 0.02) << bodies.config(b).name;
  }
}

}  // namespace
}  // namespace sluice
