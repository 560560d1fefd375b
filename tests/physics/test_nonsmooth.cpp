// The non-smooth side of the rigid core (issue 11; seed 001): contact as friction cones of a
// velocity-level step solved by APGD, and joints, run from the shipped case files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "physics_support.hpp"
#include "reported_figure.hpp"

namespace sluice {
namespace {

using testing::load_case;
using testing::run_until;

double degrees_turned(const Eigen::Quaterniond& q) {
  return 2 * std::acos(std::min(1.0, std::abs(q.w()))) * 180 / std::numbers::pi;
}

// Every body stays within `drift` of where it started and turns less than 0.1 degree.
void expect_at_rest(const std::string& name, const std::vector<std::string>& overrides, double end,
                    double drift) {
  Simulation<3> sim(load_case(name, overrides));
  const auto& bodies = sim.bodies();
  std::vector<Vec3> start;
  for (std::size_t b = 0; b < bodies.count(); ++b) start.push_back(bodies.state(b).position);
  run_until(sim, end, [](const StepClock&) {});
  double most = 0, most_angle = 0;
  for (std::size_t b = 0; b < bodies.count(); ++b) {
    most = std::max(most, (bodies.state(b).position - start[b]).norm());
    most_angle = std::max(most_angle, degrees_turned(bodies.state(b).orientation));
  }
  std::printf("%s at rest (complementarity) for %.1f s: drift %.3g mm, rotation %.3g deg\n",
              name.c_str(), end, 1e3 * most, most_angle);
  testing::expect_figure({name + " at rest (complementarity), largest drift", "mm", 5}, 1e3 * most,
                         testing::Bound::below, 1e3 * drift);
  testing::expect_figure({name + " at rest (complementarity), largest rotation", "deg", 4},
                         most_angle, testing::Bound::below, 0.1);
}

// Ten spheres of r = 0.05 m and a stack of three cubes of 0.1 m: drift below 1 % of a radius
// (half-size) in 2 s.
TEST(ComplementarityStacks, TenSpheresRest) {
  expect_at_rest("sphere_stack.yaml", {}, 2.0, 0.01 * 0.05);
}
TEST(ComplementarityStacks, ThreeCubesRest) {
  expect_at_rest("resting_cubes.yaml", {"contact.method=complementarity"}, 2.0, 0.01 * 0.05);
}

// C3 under the complementarity contact: 30 degrees with mu = 0.3 slides as Coulomb's law has
// it (within 2 %); 20 degrees with mu = 0.5 holds (creep below 1 mm in 2 s).
TEST(ComplementarityIncline, SlidesWithTheCoulombAcceleration) {
  Simulation<3> sim(load_case("incline_block.yaml", {"contact.method=complementarity"}));
  const double x0 = sim.bodies().state(0).position[0];
  run_until(sim, sim.config().end_time, [](const StepClock&) {});
  const double theta = 30 * std::numbers::pi / 180, mu = 0.3, t = sim.config().end_time;
  const double expected = 0.5 * 9.81 * (std::sin(theta) - mu * std::cos(theta)) * t * t;
  const double travelled = sim.bodies().state(0).position[0] - x0;
  std::printf("C3 (complementarity): slid %.5f m in %.2f s, analytic %.5f m (%+.2f %%)\n",
              travelled, t, expected, 100 * (travelled - expected) / expected);
  testing::expect_figure({"C3 (complementarity) slide against the analytic", "%", 2},
                         100 * (travelled / expected - 1), testing::Bound::within, 2);
}

TEST(ComplementarityIncline, HoldsWhenFrictionIsEnough) {
  const double theta = 20 * std::numbers::pi / 180;
  const std::string g = "gravity=[" + std::to_string(9.81 * std::sin(theta)) + ", 0, " +
                        std::to_string(-9.81 * std::cos(theta)) + "]";
  Simulation<3> sim(load_case(
      "incline_block.yaml",
      {g, "bodies.0.material.friction=0.5", "end_time=2.0", "contact.method=complementarity"}));
  const Vec3 start = sim.bodies().state(0).position;
  run_until(sim, 2.0, [](const StepClock&) {});
  const double creep = (sim.bodies().state(0).position - start).head<2>().norm();
  std::printf("C3 (complementarity): creep %.3g mm in 2 s\n", 1e3 * creep);
  testing::expect_figure({"C3 (complementarity) creep when friction holds", "mm", 4}, 1e3 * creep,
                         testing::Bound::below, 1);
}

// A sphere on a revolute joint released at 30 degrees: its period within 0.5 % of the exact
// one of a physical pendulum, T = 4 sqrt(I / (m g L)) K(sin(theta0 / 2)).
TEST(Joints, RevolutePendulumHasTheExactPeriod) {
  Simulation<3> sim(load_case("pendulum.yaml"));
  const Vec3 hinge(0, 0, 1.2);
  auto angle = [&] {
    const Vec3 arm = sim.bodies().state(0).position - hinge;
    return std::atan2(arm.x(), -arm.z());
  };
  std::vector<double> crossings;
  double last = angle(), last_time = 0;
  run_until(sim, sim.config().end_time, [&](const StepClock& c) {
    const double now = angle();
    if ((last < 0) != (now < 0))
      crossings.push_back(last_time + (c.time - last_time) * last / (last - now));
    last = now;
    last_time = c.time;
  });
  ASSERT_GE(crossings.size(), 3u);
  const double period = 2 * (crossings.back() - crossings.front()) / double(crossings.size() - 1);
  const double m = sim.bodies().state(0).mass, length = 1.0, r = 0.05;
  const double inertia = m * length * length + 0.4 * m * r * r;
  // K(k) by the arithmetic-geometric mean: K = pi / (2 AGM(1, sqrt(1 - k^2))).
  const double k = std::sin(15 * std::numbers::pi / 180);
  double a = 1, b = std::sqrt(1 - k * k);
  for (int n = 0; n < 20; ++n) std::tie(a, b) = std::pair(0.5 * (a + b), std::sqrt(a * b));
  const double exact = 4 * std::sqrt(inertia / (m * 9.81 * length)) * std::numbers::pi / (2 * a);
  const JointError error =
      joint_error(sim.bodies().system().rigid().joints()[0], sim.bodies().system().bodies());
  std::printf("pendulum: period %.6f s, exact %.6f s (%+.4f %%); joint error %.3g m, %.3g rad\n",
              period, exact, 100 * (period / exact - 1), error.distance, error.angle);
  testing::expect_figure({"pendulum period against the exact", "%", 4}, 100 * (period / exact - 1),
                         testing::Bound::within, 0.5);
  testing::expect_figure({"pendulum joint error", "mm", 4}, 1e3 * error.distance,
                         testing::Bound::below, 0.1);
}

// A motor spins a wheel at its set speed (5 rad/s about y).
TEST(Joints, MotorSpinsTheWheelAtItsSpeed) {
  Simulation<3> sim(load_case("motor_wheel.yaml"));
  run_until(sim, sim.config().end_time, [](const StepClock&) {});
  const Vec3 w = sim.bodies().state(0).angular_velocity();
  std::printf("motor: wheel at (%.3g, %.6f, %.3g) rad/s, set 5\n", w.x(), w.y(), w.z());
  testing::expect_figure({"motor: the wheel's spin against its set 5 rad/s", "%", 4},
                         100 * (w.y() / 5.0 - 1), testing::Bound::within, 0.1);
  testing::expect_figure({"motor: spin off the axle", "rad/s", -1}, std::hypot(w.x(), w.z()),
                         testing::Bound::below, 1e-3);
}

}  // namespace
}  // namespace sluice
