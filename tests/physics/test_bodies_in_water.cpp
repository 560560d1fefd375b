// The rigid-body checks of VALIDATION.md with fluid, and C2, run from the shipped case files
// (cases/), in process: C2, B1 to B3.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "particle_state_of.hpp"
#include "physics_support.hpp"
#include "reported_figure.hpp"

namespace sluice {
namespace {

using testing::Bound;
using testing::expect_figure;
using testing::load_case;
using testing::run_until;

// Total energy: fluid kinetic and potential, bodies' kinetic and potential, contact springs.
template <int D>
double total_energy(const Simulation<D>& sim) {
  const auto& ps = testing::particle_state(sim).particles;
  double e = sim.bodies().system().energy().total();
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (!ps.is_fluid(i)) continue;
    e += ps.mass[i] * (0.5 * ps.velocity[i].squaredNorm() -
                       testing::particle_state(sim).gravity.dot(ps.position[i]));
  }
  return e;
}

// C2: an elastic sphere hits the floor: contact time and peak overlap as Hertz's.
TEST(CaseHertzImpact, ContactTimeAndPeakOverlap) {
  Simulation<3> sim(testing::load_case("hertz_impact.yaml"));
  const auto& bodies = sim.bodies();
  const double radius = 0.1, v0 = 1.0;
  const double mass = bodies.state(0).mass;
  const double young = 1 / ((1 - 0.09) / 1e8 + (1 - 0.09) / 200e9);  // sphere and wall
  const double t_c = 2.868 * std::pow(mass * mass / (radius * young * young * v0), 0.2);
  const double peak = std::pow(15 * mass * v0 * v0 / (16 * young * std::sqrt(radius)), 0.4);
  double first = -1, last = -1, deepest = 0;
  testing::run_until(sim, sim.config().end_time, [&](const StepClock& s) {
    if (bodies.system().contact_force()[0].norm() > 0) {
      if (first < 0) first = s.time;
      last = s.time;
    }
    deepest = std::max(deepest, radius - bodies.state(0).position[2]);
  });
  const double duration = last - first + sim.config().body_interval;
  std::printf("C2 (case): contact %.4f ms (Hertz %.4f), peak overlap %.4f mm (Hertz %.4f)\n",
              1e3 * duration, 1e3 * t_c, 1e3 * deepest, 1e3 * peak);
  expect_figure({"C2 contact time against Hertz's", "%", 2}, 100 * (duration / t_c - 1),
                Bound::within, 5);
  expect_figure({"C2 peak overlap against Hertz's", "%", 2}, 100 * (deepest / peak - 1),
                Bound::within, 5);
}

}  // namespace

// B1: the floating box settles at a draft of 0.70 m within 3 %, without drifting sideways.
// The draft follows from the water's area (conserved) and the box's height: with water level h,
// 3 h = A + 1 d and d = h - (z - 0.5). The means are taken over the run's last `averaged_over`
// seconds.
testing::FloatingBoxDraft testing::floating_box_draft(const std::vector<std::string>& overrides,
                                                      double averaged_over) {
  Simulation<2> sim(testing::load_case("floating_box_2d.yaml", overrides));
  const double area = sim.fluid().observation().energy().mass / sim.config().fluid.density;
  const double x0 = sim.bodies().state(0).position[0];
  double sum = 0, offset = 0, excursion = 0;
  long samples = 0;
  const double end = sim.config().end_time;
  testing::run_until(sim, end, [&](const StepClock& s) {
    const Vec3& x = sim.bodies().state(0).position;
    if (s.time > end - averaged_over) {
      sum += (area / 3 - x[2] + 0.5) / (1 - 1.0 / 3);
      offset += x[0] - x0;
      excursion = std::max(excursion, std::abs(x[0] - x0));
      ++samples;
    }
  });
  return {sum / samples, std::abs(offset / samples), excursion};
}

namespace {

// How a model's B1 run is measured: run to `end` [s], the means over its last `averaged_over` s
// (`span` names that span in the figures; none: the last 4 s of the case's 6), and whether the
// drift is held to its bar or reported as the model's limit.
struct FloatingBoxSpan {
  double end = 6.0, averaged_over = 4.0;
  const char* span = nullptr;
  bool drift_held = true;
};

// B1 with a model: the draft within 3 % of 0.70 m, the drift below 1 cm.
void floating_box_draft(const std::string& model, const FloatingBoxSpan& how = {}) {
  const auto [draft, drift, excursion] = testing::floating_box_draft(
      {"model.name=" + model, "end_time=" + std::to_string(how.end)}, how.averaged_over);
  const std::string span = how.span ? how.span : "last 4 s";
  std::printf(
      "B1 (case, %s): mean draft over the %s %.4f m (Archimedes 0.70, %.2f %%), mean sideways "
      "offset %.3g mm, largest %.3g mm\n",
      model.c_str(), span.c_str(), draft, 100 * (draft - 0.7) / 0.7, 1e3 * drift, 1e3 * excursion);
  const std::string name = model == "wcsph" ? "B1" : "B1 `" + model + "`";
  const std::string draft_name =
      name + " draft against 0.70 m" + (how.span ? ", " + span : std::string());
  expect_figure({draft_name, "%", 2}, 100 * (draft - 0.7) / 0.7, Bound::within, 3);
  const testing::Figure offset{name + " mean sideways offset, " + span, "mm", 2};
  if (how.drift_held) {
    expect_figure(offset, 1e3 * drift, Bound::below, 10);
  } else {
    testing::report_limit(offset, 1e3 * drift, Bound::below, 10);
  }
}

TEST(CaseFloatingBox, DraftByArchimedes) {
  floating_box_draft("wcsph");
}
// MPS's box does not keep still sideways: its particles' pressure noise (F1, docs/validation.md)
// pushes it sideways by a force of 46-86 N RMS (0.7-1.3 % of its weight; wcsph's 0.4-1.2 N), and it
// wanders, by up to 4-6 cm in 12-24 s, on a path that follows the build's rounding. Its drift
// against the suite's 1 cm is therefore reported as a limit. It heaves for longer than the others'
// (its height's standard deviation 35 mm over 2-6 s against wcsph's 16), so its draft is the mean
// over 10 s (2-12 s), not the last 4 s of 6, whose mean hung on the heave's phase.
TEST(CaseFloatingBox, DraftByArchimedesWithMps) {
  floating_box_draft("mps",
                     {.end = 12.0, .averaged_over = 10.0, .span = "2-12 s", .drift_held = false});
}
TEST(CaseFloatingBox, DraftByArchimedesWithConstraintFluid) {
  floating_box_draft("constraint");
}
// The grid model's box, on the suite's bar of 1 cm: 1.4 mm in the release build, 1.7 mm in the
// baseline one (3.7 and 6.3 mm, and a bar of 3 cm, before issue 14 made the sweeping of its level
// set and velocity extension mirror-symmetric).
TEST(CaseFloatingBox, DraftByArchimedesWithMac) {
  floating_box_draft("mac");
}

TEST(CaseFallingCube, SinksAndRestsOnTheFloor) {
  Simulation<3> sim(testing::load_case("falling_cube.yaml", {"end_time=0.4"}));
  const double half = 0.01, dx = sim.config().spacing;
  double lowest = 1;
  testing::run_until(sim, sim.config().end_time, [&](const StepClock&) {
    lowest = std::min(lowest, sim.bodies().state(0).position[2] - half);
  });
  const auto& s = sim.bodies().state(0);
  std::printf("B2 (case): cube bottom at %.3g mm at the end, lowest %.3g mm, speed %.3g mm/s\n",
              1e3 * (s.position[2] - half), 1e3 * lowest, 1e3 * s.velocity.norm());
  expect_figure({"B2 cube, deepest below the floor", "mm", 3}, 1e3 * lowest, Bound::above,
                -1e3 * 0.1 * dx);
  expect_figure({"B2 cube, above the floor at the end", "mm", 3}, 1e3 * (s.position[2] - half),
                Bound::below, 1e3 * 0.1 * dx);
  expect_figure({"B2 cube, speed at the end", "mm/s", 3}, 1e3 * s.velocity.norm(), Bound::below,
                10);
}

// B2: the light block floats: it never touches the floor and keeps its draft near Archimedes'.
TEST(CaseFloatingBlock, Floats) {
  Simulation<3> sim(testing::load_case("floating_block.yaml", {"spacing=0.005", "end_time=0.3"}));
  const double half_height = 0.012, water = 0.052, archimedes = 0.80052 * 0.024;
  double lowest = 1, sum = 0;
  long samples = 0;
  testing::run_until(sim, sim.config().end_time, [&](const StepClock& s) {
    const double bottom = sim.bodies().state(0).position[2] - half_height;
    lowest = std::min(lowest, bottom);
    if (s.time > 0.5 * sim.config().end_time) {
      sum += water - bottom;  // the water level rises by under 2 % of the draft: ignored
      ++samples;
    }
  });
  const double draft = sum / samples;
  std::printf(
      "B2 (case): block lowest bottom %.3g mm above the floor, mean draft %.4g mm "
      "(Archimedes %.4g)\n",
      1e3 * lowest, 1e3 * draft, 1e3 * archimedes);
  expect_figure({"B2 block, lowest above the floor", "mm", 2}, 1e3 * lowest, Bound::above,
                1e3 * 0.25 * water);
  expect_figure({"B2 block draft against Archimedes'", "%", 2}, 100 * (draft / archimedes - 1),
                Bound::within, 10);
}

// B3: dam break on six cubes at a coarse spacing to 1.5 s: no interpenetration beyond a tenth of
// the spacing, no body leaves the tank, the total energy never grows (beyond 0.5 % of the
// start, which the weakly compressible fluid's elastic energy, not counted here, can exchange).
TEST(CaseDamBreakCubes, SixCubesStaySound) {
  Simulation<3> sim(testing::load_case("dam_break_cubes_6.yaml", {"spacing=0.05", "end_time=1.5"}));
  const double dx = sim.config().spacing;
  const double start = total_energy(sim);
  double lowest = start, worst_rise = 0, moved = 0;
  bool inside = true;
  const auto& tank = sim.config().walls[0].box;
  std::vector<Vec3> initial;
  for (std::size_t b = 0; b < sim.bodies().count(); ++b)
    initial.push_back(sim.bodies().state(b).position);
  testing::run_until(sim, sim.config().end_time, [&](const StepClock&) {
    const double e = total_energy(sim);
    worst_rise = std::max(worst_rise, e - lowest);
    lowest = std::min(lowest, e);
    for (std::size_t b = 0; b < sim.bodies().count(); ++b) {
      inside = inside && tank.contains(sim.bodies().state(b).position, 3);
    }
  });
  for (std::size_t b = 0; b < sim.bodies().count(); ++b)
    moved = std::max(moved, (sim.bodies().state(b).position - initial[b]).norm());
  const double overlap = sim.bodies().system().deepest_overlap_ever();
  std::printf(
      "B3 (case): deepest overlap %.3g mm (%.3g dx), largest energy rise %.3g %% of the "
      "start, energy %.1f -> %.1f J, largest body displacement %.3g m\n",
      1e3 * overlap, overlap / dx, 100 * worst_rise / start, start, total_energy(sim), moved);
  expect_figure({"B3 deepest overlap", "spacings", 4}, overlap / dx, Bound::below, 0.1);
  EXPECT_TRUE(inside);
  expect_figure({"B3 largest energy rise", "% of the start", 3}, 100 * worst_rise / start,
                Bound::below, 0.5);
}

}  // namespace
}  // namespace sluice
