// The particle models' open boundaries (fluid/particle_open_boundaries.hpp): an inlet's buffer
// moves at the inflow's velocity and refills itself behind each particle that leaves it, an
// outlet's buffer takes the fluid that enters it, moves at the velocity of the fluid beside it
// and drops what leaves the domain, fluid that
// drifts back into an inlet's buffer goes, the flux
// estimate reads a moving lattice's flux exactly, and an outlet's pressure is hydrostatic below
// its depth.
#include <gtest/gtest.h>

#include <cmath>

#include "sluice/fluid/particle_open_boundaries.hpp"

namespace sluice {
namespace {

using Vec2 = Vec<2>;

constexpr double kDx = 0.1;
constexpr int kLayers = 2;  // buffers 0.2 m deep

// A 2 m x 1 m domain (2D, x-z) with an inlet on x- and an outlet on x+, both 0.6 m deep.
ParticleOpenBoundaries<2> channel(io::InletProfile profile = io::InletProfile::kUniform) {
  io::BoundaryConfig in, out;
  in.kind = io::BoundaryKind::kInlet;
  in.mean_speed = 0.5;
  in.profile = profile;
  in.depth = 0.6;
  out.kind = io::BoundaryKind::kOutlet;
  out.upper = true;
  out.depth = 0.6;
  out.pressure = 100;
  AxisBox domain;
  domain.max = Vec3(2, 0, 1);
  return ParticleOpenBoundaries<2>({in, out}, domain, kDx, kLayers, 1000, -10);
}

struct Particles {
  ParticleSet<2> set;
  FieldHandle<std::int32_t> zone = set.add_int_field({"open_boundary", "1", true});
  void add(double x, double z, double u, ParticleKind kind, int in_zone) {
    set.add(Vec2(x, z), Vec2(u, 0), 1000, 1000 * kDx * kDx, kind);
    set[zone].back() = in_zone;
  }
};

TEST(ParticleOpenBoundaries, InletBufferLiesBelowItsDepthAndCarriesItsMeanSpeed) {
  const ParticleOpenBoundaries<2> uniform = channel();
  const auto buffers = uniform.inlet_buffers();
  ASSERT_EQ(buffers.size(), 1u);
  EXPECT_EQ(buffers[0].first, 0u);
  EXPECT_DOUBLE_EQ(buffers[0].second.max[0], 0.2);
  EXPECT_DOUBLE_EQ(buffers[0].second.max[2], 0.6);
  EXPECT_TRUE(uniform.in_inlet_buffer(Vec2(0.19, 0.3)));
  EXPECT_FALSE(uniform.in_inlet_buffer(Vec2(0.21, 0.3)));
  EXPECT_FALSE(uniform.in_inlet_buffer(Vec2(1.9, 0.3)));  // an outlet's
  EXPECT_EQ(uniform.inflow_velocity(0, Vec2(0.1, 0.3), 0), Vec2(0.5, 0));
  // The parabola over the 0.6 m below the depth: its mean over the six rows of particles is
  // 1 + 1/(2 * 6^2) of the mean speed.
  const ParticleOpenBoundaries<2> parabolic = channel(io::InletProfile::kParabolic);
  double sum = 0;
  for (int k = 0; k < 6; ++k) sum += parabolic.inflow_velocity(0, Vec2(0.1, (k + 0.5) * kDx), 0)[0];
  EXPECT_NEAR(sum / 6, 0.5 * (1 + 1.0 / 72), 1e-12);
  EXPECT_NEAR(parabolic.inflow_velocity(0, Vec2(0.1, 0.3), 0)[0], 0.75, 1e-12);
}

TEST(ParticleOpenBoundaries, InletRefillsItsBufferBehindEachParticleThatLeavesIt) {
  const ParticleOpenBoundaries<2> open = channel();
  Particles p;
  p.add(0.15, 0.05, 0.5, ParticleKind::kWall, 1);  // 0.05 m from the buffer's inner face
  p.add(0.05, 0.05, 0.5, ParticleKind::kWall, 1);
  p.add(1.0, 0.05, 0.5, ParticleKind::kFluid, 0);
  std::vector<bool> gone;
  BufferHandOver hand_over;
  // 0.12 s at 0.5 m/s: the first crosses into the domain, the second stays in the buffer.
  open.advance(p.set, p.zone, 0, 0.12, gone, hand_over);
  ASSERT_EQ(p.set.size(), 4u);
  EXPECT_EQ(hand_over.joined, std::vector<std::uint32_t>{0});
  EXPECT_TRUE(hand_over.left.empty());
  EXPECT_EQ(p.set.kind[0], ParticleKind::kFluid);
  EXPECT_EQ(p.set[p.zone][0], 0);
  EXPECT_NEAR(p.set.position[0][0], 0.21, 1e-12);
  EXPECT_EQ(p.set.kind[1], ParticleKind::kWall);
  EXPECT_NEAR(p.set.position[1][0], 0.11, 1e-12);
  EXPECT_NEAR(p.set.position[2][0], 1.0, 1e-12);  // the model moves the fluid, not the buffer
  // Its copy, one buffer's depth back, in the buffer at the inflow's velocity.
  EXPECT_EQ(p.set.kind[3], ParticleKind::kWall);
  EXPECT_EQ(p.set[p.zone][3], 1);
  EXPECT_NEAR(p.set.position[3][0], 0.01, 1e-12);
  EXPECT_EQ(p.set.velocity[3], Vec2(0.5, 0));
  EXPECT_EQ(gone, std::vector<bool>(4, false));
}

TEST(ParticleOpenBoundaries, OutletTakesTheFluidThatEntersItAndDropsWhatLeavesTheDomain) {
  const ParticleOpenBoundaries<2> open = channel();
  Particles p;
  p.add(1.85, 0.05, 0.4, ParticleKind::kFluid, 0);  // in the outlet's buffer: joins it
  p.add(1.75, 0.05, 0.6, ParticleKind::kFluid, 0);  // before it: stays fluid
  p.add(1.97, 0.05, 0.4, ParticleKind::kWall, 2);   // leaves the domain
  p.add(1.81, 0.45, -0.4, ParticleKind::kWall, 2);  // turns back (no fluid beside): fluid again
  EXPECT_EQ(open.start(p.set, p.zone), 1u);
  EXPECT_EQ(p.set.kind[0], ParticleKind::kWall);
  EXPECT_EQ(p.set[p.zone][0], 2);
  // And one more fluid particle that enters the buffer in the pass.
  p.add(1.82, 0.15, 0.4, ParticleKind::kFluid, 0);
  std::vector<bool> gone;
  BufferHandOver hand_over;
  open.advance(p.set, p.zone, 0, 0.1, gone, hand_over);
  EXPECT_EQ(gone, (std::vector<bool>{false, false, true, false, false}));
  EXPECT_EQ(hand_over.joined, std::vector<std::uint32_t>{3});
  EXPECT_EQ(hand_over.left, std::vector<std::uint32_t>{4});
  EXPECT_EQ(p.set.kind[4], ParticleKind::kWall);
  EXPECT_EQ(p.set[p.zone][4], 2);
  EXPECT_NEAR(p.set.position[0][0], 1.91, 1e-12);  // on at the velocity of the fluid beside
  EXPECT_EQ(p.set.kind[1], ParticleKind::kFluid);
  EXPECT_EQ(p.set.kind[3], ParticleKind::kFluid);
  EXPECT_EQ(p.set[p.zone][3], 0);
}

// An outlet's buffer particle moves at the mean velocity of the fluid within two spacings inside
// the buffer's face at its height (in strips two spacings high), whatever velocity it had; one
// with no fluid at its height keeps its own, and so does a ghost (its owned kind -1).
TEST(ParticleOpenBoundaries, OutletBufferTakesTheVelocityOfTheFluidBesideIt) {
  const ParticleOpenBoundaries<2> open = channel();
  Particles p;
  const auto owned = p.set.add_int_field({"owned_kind", "1", false});
  p.add(1.75, 0.05, 0.2, ParticleKind::kFluid, 0);  // the strip 0 to 0.2 m high
  p.add(1.65, 0.15, 0.4, ParticleKind::kFluid, 0);
  p.add(1.55, 0.15, 9.0, ParticleKind::kFluid, 0);  // farther than two spacings: not counted
  p.add(1.75, 0.25, 0.6, ParticleKind::kFluid, 0);  // the strip 0.2 to 0.4 m
  p.add(1.85, 0.10, 0.0, ParticleKind::kWall, 2);   // buffer particles
  p.add(1.95, 0.30, 0.0, ParticleKind::kWall, 2);
  p.add(1.85, 0.50, 0.1, ParticleKind::kWall, 2);  // no fluid at its height
  p.add(1.85, 0.10, 0.0, ParticleKind::kWall, 2);  // a ghost
  for (std::size_t i = 0; i < p.set.size(); ++i) p.set[owned][i] = i == 7 ? -1 : 0;
  std::vector<bool> gone;
  BufferHandOver hand_over;
  open.advance(p.set, p.zone, 0, 0.01, gone, hand_over, owned);
  EXPECT_NEAR(p.set.velocity[4][0], 0.3, 1e-12);
  EXPECT_NEAR(p.set.velocity[5][0], 0.6, 1e-12);
  EXPECT_NEAR(p.set.velocity[6][0], 0.1, 1e-12);
  EXPECT_EQ(p.set.velocity[7][0], 0.0);
  EXPECT_NEAR(p.set.position[4][0], 1.853, 1e-12);  // moved at its new velocity
}

// Fluid that drifts back into an inlet's buffer (or past the side) goes; fluid before the
// buffer's face stays, and a ghost (its owned kind -1) is left to its owner.
TEST(ParticleOpenBoundaries, InletDropsTheFluidThatDriftsBackIntoItsBuffer) {
  const ParticleOpenBoundaries<2> open = channel();
  Particles p;
  const auto owned = p.set.add_int_field({"owned_kind", "1", false});
  p.add(0.15, 0.05, -0.1, ParticleKind::kFluid, 0);   // in the buffer: goes
  p.add(-0.01, 0.05, -0.1, ParticleKind::kFluid, 0);  // past the side: goes
  p.add(0.25, 0.05, -0.1, ParticleKind::kFluid, 0);   // before the face: stays
  p.add(0.12, 0.05, -0.1, ParticleKind::kFluid, 0);   // a ghost: its owner's
  for (std::size_t i = 0; i < 4; ++i) p.set[owned][i] = i == 3 ? -1 : 0;
  std::vector<bool> gone;
  BufferHandOver hand_over;
  open.advance(p.set, p.zone, 0, 0.1, gone, hand_over, owned);
  EXPECT_EQ(gone, (std::vector<bool>{true, true, false, false}));
  EXPECT_EQ(hand_over.dropped, (std::vector<std::uint32_t>{0, 1}));
  EXPECT_TRUE(hand_over.joined.empty());
  EXPECT_TRUE(hand_over.left.empty());
}

TEST(ParticleOpenBoundaries, FluxThroughTheInnerFaceOfAMovingLatticeIsItsSpeedTimesItsDepth) {
  const ParticleOpenBoundaries<2> open = channel();
  for (double shift : {0.0, 0.013, 0.05, 0.0731}) {
    Particles p;
    for (int i = 0; i < 20; ++i) {
      for (int k = 0; k < 6; ++k) {
        const double x = (i + 0.5) * kDx + shift;
        const bool buffer = x < 0.2;
        p.add(x, (k + 0.5) * kDx, 0.5, buffer ? ParticleKind::kWall : ParticleKind::kFluid,
              buffer ? 1 : 0);
      }
    }
    // Inflow (into the domain) is negative; 0.5 m/s over 0.6 m.
    EXPECT_NEAR(open.outflow(p.set, p.zone, 0), -0.3, 1e-12) << shift;
    EXPECT_NEAR(open.outflow(p.set, p.zone, 1), 0.3, 1e-12) << shift;
  }
}

TEST(ParticleOpenBoundaries, OutletPressureIsItsOwnAndHydrostaticBelowItsDepth) {
  const ParticleOpenBoundaries<2> open = channel();
  Particles p;
  p.add(1.9, 0.1, 0.4, ParticleKind::kWall, 2);
  p.add(1.9, 0.8, 0.4, ParticleKind::kWall, 2);  // above the depth
  p.add(1.0, 0.1, 0.4, ParticleKind::kFluid, 0);
  p.set.pressure[2] = 7;
  open.prescribe_outlet_pressure(p.set, p.zone, [](Real pressure) { return 1000 + pressure; });
  EXPECT_NEAR(p.set.pressure[0], 100 + 1000 * 10 * 0.5, 1e-9);
  EXPECT_NEAR(p.set.density[0], 1000 + 5100, 1e-9);
  EXPECT_NEAR(p.set.pressure[1], 100, 1e-12);
  EXPECT_EQ(p.set.pressure[2], 7);  // fluid: the model's
}

}  // namespace
}  // namespace sluice
