// The transport velocity's background acceleration (fluid/wcsph/transport_velocity.hpp),
// b_i = -(p_b / m_i) sum_j (V_i^2 + V_j^2) grad W_ij: against a plain double-precision sum over
// every pair on a disturbed lattice with walls and a body, and on an even lattice, where it
// vanishes but for one particle moved off its place, which it pushes back.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "sluice/fluid/wcsph/wcsph_model.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/kernels/wendland_c2.hpp"
#include "sluice/sim/rigid_bodies.hpp"

namespace sluice {
namespace {

constexpr double kBackgroundPressure = 50;  // Pa
constexpr double kDx = 0.01;

io::CaseConfig tank_case() {
  return io::parse_case(
      "dimension: 2\nspacing: 0.01\ndomain: {min: [0, 0], max: [0.3, 0.3]}\n"
      "end_time: 1\noutput_interval: 0.1\n"
      "fluid:\n  blocks:\n    - {min: [0, 0], max: [0.3, 0.2]}\n"
      "walls:\n  - {type: tank, min: [0, 0], max: [0.3, 0.3], open: [z+]}\n"
      "bodies:\n  - {shape: box, size: [0.05, 0.05], density: 800, position: [0.15, 0.12]}\n"
      "model:\n  name: wcsph\n  background_pressure: 50\n",
      "transport_velocity.yaml");
}

using Model = WcsphModel<2, WendlandC2<2>>;

// The model's background acceleration of each particle after `move` shifted the particles and
// the model worked out its first rates; `reference` gets the double-precision sum.
struct Evaluation {
  std::vector<Vec<2>> background, reference;
  std::vector<Vec<2>> position;
  std::vector<bool> fluid;
};

template <class Move>
Evaluation evaluate(Move&& move) {
  const io::CaseConfig config = tank_case();
  const WcsphParameters p = read_wcsph_parameters(config);
  const RigidBodies bodies(config);
  Model model(p, config, bodies);
  ParticleState<2>& s = model.state();
  auto& ps = s.particles;
  move(ps);
  std::vector<std::uint32_t> order;
  s.cells.sort(ps.position, order);
  ps.reorder(order);
  model.initialize();
  const Real* b = ps.template components<Real>("background_acceleration");
  const WendlandC2<2> kernel(p.smoothing_length(config.spacing));
  Evaluation out;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    out.background.emplace_back(b[2 * i], b[2 * i + 1]);
    out.position.push_back(ps.position[i]);
    out.fluid.push_back(ps.is_fluid(i));
    Vec<2> sum = Vec<2>::Zero();
    if (ps.is_fluid(i)) {
      const double volume_i = ps.mass[i] / ps.density[i];
      for (std::size_t j = 0; j < ps.size(); ++j) {
        const Vec<2> r = ps.position[i] - ps.position[j];
        if (j == i || r.norm() >= kernel.support()) continue;
        const double volume_j = ps.mass[j] / ps.density[j];
        sum += (volume_i * volume_i + volume_j * volume_j) * kernel.gradient_factor(r.norm()) * r;
      }
      sum *= -kBackgroundPressure / ps.mass[i];
    }
    out.reference.push_back(sum);
  }
  return out;
}

TEST(WcsphTransportVelocity, MatchesTheDoubleLoopOnADisturbedLattice) {
  std::mt19937 random(4321);
  std::uniform_real_distribution<double> unit(-1, 1);
  const Evaluation e = evaluate([&](ParticleSet<2>& ps) {
    for (std::size_t i = 0; i < ps.size(); ++i)
      if (ps.is_fluid(i))
        for (int a = 0; a < 2; ++a) ps.position[i][a] += 0.25 * kDx * unit(random);
  });
  double deviation = 0, scale = 0;
  for (std::size_t i = 0; i < e.background.size(); ++i) {
    if (!e.fluid[i]) continue;
    deviation = std::max(deviation, (e.background[i] - e.reference[i]).norm());
    scale = std::max(scale, e.reference[i].norm());
  }
  std::printf("largest deviation %.3g of %.3g m/s^2\n", deviation, scale);
  EXPECT_GT(scale, 0);
  EXPECT_LT(deviation, 1e-4 * scale);  // single precision's sums of some 30 pair terms
}

TEST(WcsphTransportVelocity, VanishesOnAnEvenLatticeAndPushesAMovedParticleBack) {
  const Vec<2> moved_from(0.055, 0.055);  // a lattice site, four spacings from wall and body
  auto at_site = [&](const Vec<2>& x) { return (x - moved_from).norm() < 0.1 * kDx; };
  const Evaluation even = evaluate([](ParticleSet<2>&) {});
  double largest = 0;
  for (std::size_t i = 0; i < even.background.size(); ++i) {
    // Away from the free surface (0.2 m), where the sum has no neighbours above, and from the
    // body, whose particles lie farther from the fluid's than a spacing (the fluid closer than
    // 0.4 dx to its surface was not placed), so that b draws the fluid towards it.
    const Vec<2> x = even.position[i];
    const bool near_body = x[0] > 0.095 && x[0] < 0.205 && x[1] > 0.065;
    if (even.fluid[i] && x[1] < 0.15 && !near_body)
      largest = std::max(largest, even.background[i].norm());
  }
  const Evaluation moved = evaluate([&](ParticleSet<2>& ps) {
    for (std::size_t i = 0; i < ps.size(); ++i)
      if (at_site(ps.position[i])) ps.position[i][0] += 0.2 * kDx;
  });
  Vec<2> push = Vec<2>::Zero();
  for (std::size_t i = 0; i < moved.background.size(); ++i)
    if (at_site(moved.position[i] - Vec<2>(0.2 * kDx, 0))) push = moved.background[i];
  std::printf("even lattice: largest %.3g m/s^2; moved by 0.2 dx: (%.3g, %.3g) m/s^2\n", largest,
              push[0], push[1]);
  EXPECT_LT(push[0], -100 * largest);  // back towards its site
  EXPECT_LT(std::abs(push[1]), -0.01 * push[0]);
}

}  // namespace
}  // namespace sluice
