// The granular model (issue 11; seed 001's fourth method): water as frictionless spheres in the
// bodies' velocity-level step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <fmt/format.h>
#include <numbers>

#include "particle_state_of.hpp"
#include "physics_support.hpp"
#include "reported_figure.hpp"
#include "sluice/fluid/granular/granular_model.hpp"

namespace sluice {
namespace {

using testing::load_case;
using testing::run_until;

// The vertical force the walls put on the spheres over the last step [N, or N/m in 2D].
template <int D>
double wall_lift(const Simulation<D>& sim) {
  const auto& model = dynamic_cast<const GranularModel<D>&>(sim.fluid());
  const SphereContacts& contacts = model.sphere_contacts();
  double lift = 0;
  for (std::size_t c = 0; c < contacts.contacts().size(); ++c) {
    if (contacts.contacts()[c].a != SphereContacts::kWorld) continue;
    lift += contacts.normal_impulse(c) * contacts.contacts()[c].normal.z();
  }
  return lift / sim.clock().dt;
}

// A pool at rest presses on the floor with its weight, within 1 % (mean over the last 0.5 s).
TEST(Granular, PoolAtRestPressesWithItsWeight) {
  Simulation<2> sim(load_case("granular_pool_2d.yaml", {"end_time=1.0"}));
  const double weight = sim.fluid().observation().energy().mass * 9.81;
  double impulse = 0, duration = 0;
  run_until(sim, 1.0, [&](const StepClock& c) {
    if (c.time <= 0.5) return;
    impulse += wall_lift(sim) * c.dt;
    duration += c.dt;
  });
  const double mean = impulse / duration;
  std::printf("granular pool: floor carries %.5g N/m, weight %.5g N/m (%+.3f %%)\n", mean, weight,
              100 * (mean / weight - 1));
  testing::expect_figure({"`granular` pool, the floor's load against the weight", "%", 3},
                         100 * (mean / weight - 1), testing::Bound::within, 1);
}

// Same answer on one and two threads, bit for bit: the sphere contacts are found block by
// block and joined in order, each sphere's impulses summed by one thread, the solver's dot
// products in fixed blocks.
TEST(Granular, SameOnOneAndTwoThreads) {
  const auto [one, two] = testing::on_one_and_two_threads([] {
    Simulation<2> sim(load_case("dam_break_2d.yaml", {"model.name=granular", "spacing=0.05"}));
    run_until(sim, 0.1, [](const StepClock&) {});
    return testing::particle_state(sim).particles;
  });
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    ASSERT_EQ(one.position[i], two.position[i]) << i;
    ASSERT_EQ(one.velocity[i], two.velocity[i]) << i;
  }
}

// A box of density 700 set down on a pool of spheres sinks, slower and slower as the pool
// settles under it (about 7 s). Checked, what the model can meet: the box stays afloat (its
// bottom far above the floor) and settles (over its last 2 s it moves less than 2 % of what
// it sank in its first 2 s; it still creeps, a few mm a second, as the pool packs). Not met, and
// stated as the method's limit in docs/validation.md (not asserted): Archimedes' draft. A
// frictionless packing is a jammed solid that carries the box on force chains, and the box floats a
// third higher (-33 %) than in a liquid of the pool's bulk density; the line printed gives the
// draft against Archimedes' (issue 11 is blocked on it).
TEST(Granular, BoxFloatsOnThePool) {
  Simulation<2> sim(load_case("granular_floating_box_2d.yaml"));
  // The box's height, its mean over the last 2 s (each step weighted by its length) and how far
  // it moved over them.
  const double start = sim.bodies().state(0).position.z();
  double height = 0, duration = 0, lowest = 1e300, highest = -1e300, after_two_seconds = start;
  run_until(sim, 9.0, [&](const StepClock& c) {
    if (c.time <= 2.0) after_two_seconds = sim.bodies().state(0).position.z();
    if (c.time <= 7.0) return;
    const double z = sim.bodies().state(0).position.z();
    height += z * c.dt;
    duration += c.dt;
    lowest = std::min(lowest, z);
    highest = std::max(highest, z);
  });
  height /= duration;
  // Archimedes without a surface to measure: the box floats where the pool beside it (within
  // 0.5 m of the walls) holds, above the level of the box's bottom, the box's mass per unit
  // width (700 kg/m^2): the pressure there is the weight above it. The draft follows from the
  // pool's bulk density (its packing between 0.2 and 1 m up times the spheres' density).
  const auto& ps = testing::particle_state(sim).particles;
  const auto& model = dynamic_cast<const GranularModel<2>&>(sim.fluid());
  const double bottom = height - 0.5;
  double area = 0, mass = 0, above = 0;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (!ps.is_fluid(i)) continue;
    const double x = ps.position[i][0], z = ps.position[i][1];
    if (x >= 0.5 && x <= 2.5) continue;
    if (z > bottom) above += ps.mass[i];
    if (z > 0.2 && z < 1.0) {
      const double r = model.radius_of(i);
      area += std::numbers::pi * r * r;
      mass += ps.mass[i];
    }
  }
  const double window = 2 * 0.5 * 0.8, packing = area / window, bulk = mass / window;
  const double overburden = above / (2 * 0.5), box = 700 * 1.0;  // [kg/m^2]
  std::printf(
      "granular box: bottom %.3f m above the floor, sank %.1f mm in the first 2 s and moved %.3f "
      "mm over the last 2 s; packing "
      "%.3f, bulk density %.0f kg/m^3; beside the box, %.1f kg/m^2 of spheres above its bottom "
      "against its %.0f kg/m^2: a draft %.3f m against Archimedes' %.3f m (%+.0f %%, the "
      "method's limit)\n",
      bottom, 1e3 * (start - after_two_seconds), 1e3 * (highest - lowest), packing, bulk,
      overburden, box, overburden / bulk, box / bulk, 100 * (overburden / box - 1));
  EXPECT_GT(bottom, 0.5);                                           // afloat: far above the floor
  EXPECT_LT(highest - lowest, 0.02 * (start - after_two_seconds));  // settles
}

// The runout of a collapsed column: the farthest edge of the grains in contact (within a
// tenth of a radius), directly or through others, with the grain nearest the wall's foot;
// grains thrown clear do not count (validation/column_collapse.py measures it the same way).
double deposit_front(const Simulation<2>& sim) {
  const auto& ps = testing::particle_state(sim).particles;
  const auto& model = dynamic_cast<const GranularModel<2>&>(sim.fluid());
  std::vector<std::size_t> grains;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (ps.is_fluid(i)) grains.push_back(i);
  }
  auto at = [&](std::size_t g) { return ps.position[grains[g]]; };
  auto radius = [&](std::size_t g) { return model.radius_of(grains[g]); };
  std::size_t start = 0;
  for (std::size_t g = 1; g < grains.size(); ++g) {
    if (at(g).sum() < at(start).sum()) start = g;
  }
  std::vector<bool> seen(grains.size(), false);
  std::vector<std::size_t> stack{start};
  seen[start] = true;
  double front = 0;
  while (!stack.empty()) {
    const std::size_t g = stack.back();
    stack.pop_back();
    front = std::max(front, at(g)[0] + radius(g));
    for (std::size_t k = 0; k < grains.size(); ++k) {
      if (seen[k] || (at(k) - at(g)).norm() >= radius(k) + 1.1 * radius(g)) continue;
      seen[k] = true;
      stack.push_back(k);
    }
  }
  return front;
}

// Lube, Huppert, Sparks & Freundt (Phys. Rev. E 72, 2005), quasi-2D columns: the runout
// (L_inf - L0) / L0 is 1.2 a for aspect ratios a below about 1.8 and 1.9 a^(2/3) above about
// 2.8. Each column's smaller side is 20 grains (cases/column_collapse_2d.yaml). At a = 0.5 the
// bar is 15 % of 1.2 a; a = 2 lies between the laws (2.4 and 3.02), and the bar is the band
// from 15 % below the one to 15 % above the other. The runout is the mean over `packings`
// packings of the same column (model.packing_seed 0, 1, ...): one packing's runout hangs on the
// rounding of its first contacts, and the mean's spread between builds is the smaller.
void expect_runout(double a, double low, double high, int packings = 1) {
  const double width = a < 1 ? 0.2 / a : 0.2;
  double runout = 0;
  for (int seed = 0; seed < packings; ++seed) {
    Simulation<2> sim(load_case("column_collapse_2d.yaml",
                                {fmt::format("fluid.blocks.0.max=[{},{}]", width, a * width),
                                 fmt::format("model.packing_seed={}", seed)}));
    run_until(sim, 1.5, [](const StepClock&) {});
    const double one = (deposit_front(sim) - width) / width;
    std::printf("column collapse a = %g, packing %d: (L_inf - L0)/L0 = %.3f\n", a, seed, one);
    runout += one / packings;
  }
  std::printf(
      "column collapse a = %g: (L_inf - L0)/L0 = %.3f over %d packing(s) (Lube: 1.2 a = %.3f, "
      "1.9 a^(2/3) = %.3f; bar %.3f-%.3f)\n",
      a, runout, packings, 1.2 * a, 1.9 * std::pow(a, 2.0 / 3), low, high);
  const std::string name = fmt::format("column collapse a = {}, (L_inf - L0)/L0", a);
  testing::expect_figure({name + ", the band's low end", "", 3}, runout, testing::Bound::above,
                         low);
  testing::expect_figure({name + ", the band's high end", "", 3}, runout, testing::Bound::below,
                         high);
}

// As the mean of six packings too: one packing's runout, 0.610 and 0.531 in the release and
// baseline builds after a run's steps became equal between outputs (issue 39), lay 0.26 of that
// spread from the band's low end.
TEST(Granular, ColumnCollapseRunoutLowColumn) {
  expect_runout(0.5, 0.85 * 0.6, 1.15 * 0.6, 6);
}

TEST(Granular, ColumnCollapseRunoutTallColumn) {
  expect_runout(2.0, 0.85 * 2.4, 1.15 * 1.9 * std::pow(2.0, 2.0 / 3));
}

// The rolling friction (0.15) was chosen on a = 0.5 and a = 2 (docs/validation.md); a = 1 is
// out of that sample: Lube et al.'s 1.2 a within 15 %, as the mean of six packings. One
// packing's runout, 1.138 and 1.101 in the release and baseline builds, lay 2.2 spreads from the
// band's low end; the first three packings scatter over 1.04-1.24 across the two builds (standard
// deviation 0.065), so the mean of six has a standard error of about 0.026 against a margin of
// about 0.1.
TEST(Granular, ColumnCollapseRunoutOutOfSample) {
  expect_runout(1.0, 0.85 * 1.2, 1.15 * 1.2, 6);
}

}  // namespace
}  // namespace sluice
