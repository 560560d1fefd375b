// One fluid particle of the penalty-sph model against a layer of solid particles
// (fluid/penalty_sph/solid_contact_stepper.hpp): free flight is exact, a stiff layer stops a
// falling particle and holds it at rest under gravity at any step, and a soft one lets it
// through once its kinetic energy beats the penalty energy at the layer's weakest point.
#include <gtest/gtest.h>

#include "sluice/fluid/penalty_sph/solid_contact_stepper.hpp"

namespace sluice {
namespace {

constexpr Real kFluidSpacing = 0.0033;
constexpr Real kMass = 998.29 * kFluidSpacing * kFluidSpacing * kFluidSpacing;
constexpr Real kDensity = 998.29;

// A square layer of solid particles L_b apart in the plane z = 0, 0.1 m wide.
SolidParticles<3> layer(Real spacing) {
  ParticleSet<3> particles;
  std::vector<Real> solid_spacing;
  const int n = static_cast<int>(0.1 / spacing);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      particles.add(Vec3((i + 0.5) * spacing, (j + 0.5) * spacing, 0), Vec3::Zero(), 2800, 1,
                    ParticleKind::kWall);
      solid_spacing.push_back(spacing);
    }
  }
  SolidParticles<3> solids;
  solids.gather(particles, solid_spacing, kFluidSpacing, 0.0055);
  return solids;
}

SolidContactSettings<3> settings(Real stiffness) {
  SolidContactSettings<3> s;
  s.law = {stiffness, 2 * std::sqrt(stiffness * kMass)};
  s.kernels = MullerKernels<3>(0.0055);
  return s;
}

const Vec3 kGravity(0, 0, -9.81);

TEST(SolidContactStepper, FreeFlightIsExact) {
  const SolidParticles<3> solids = layer(0.002);
  std::vector<SolidCandidate> scratch;
  Vec3 x(0.05, 0.05, 0.3), v(0.1, 0, -1);
  const auto r = advance_against_solids<3>(settings(5e4), solids.view(), x, v, kMass, kDensity,
                                           kGravity, 0.01, scratch);
  EXPECT_FALSE(r.touched);
  EXPECT_EQ(r.impulse.norm(), 0);
  EXPECT_NEAR((x - Vec3(0.051, 0.05, 0.3 - 0.01 - 0.5 * 9.81e-4)).norm(), 0, 1e-14);
  EXPECT_NEAR((v - Vec3(0.1, 0, -1 - 0.0981)).norm(), 0, 1e-14);
}

// Drops a particle from 0.3 m above the layer at (x, y) and runs `steps` steps of 0.01 s.
struct Drop {
  Vec3 x, v;
  bool crossed_plane = false;
  Vec3 last_force = Vec3::Zero();
};
Drop drop(Real stiffness, Real solid_spacing, Real x0, Real y0, int steps) {
  const SolidParticles<3> solids = layer(solid_spacing);
  const SolidContactSettings<3> s = settings(stiffness);
  std::vector<SolidCandidate> scratch;
  Drop d{Vec3(x0, y0, 0.01), Vec3(0, 0, -std::sqrt(2 * 9.81 * 0.3))};
  for (int k = 0; k < steps; ++k) {
    const auto r = advance_against_solids<3>(s, solids.view(), d.x, d.v, kMass, kDensity, kGravity,
                                             0.01, scratch);
    d.crossed_plane = d.crossed_plane || d.x.z() < 0;
    d.last_force = r.impulse / 0.01;
  }
  return d;
}

TEST(SolidContactStepper, ABoundedListTooShortVoidsTheStep) {
  // A device's scratch (BoundedList) holds 4 solids; on the layer the particle meets dozens.
  const SolidParticles<3> solids = layer(0.002);
  BoundedList<SolidCandidate, 4> scratch;
  Vec3 x(0.05, 0.05, 0.002), v(0, 0, -1);
  const auto r = advance_against_solids<3>(settings(5e4), solids.view(), x, v, kMass, kDensity,
                                           kGravity, 0.01, scratch);
  EXPECT_TRUE(r.overflowed);
  // With room for all of them, the same step holds.
  BoundedList<SolidCandidate, 512> room;
  Vec3 y(0.05, 0.05, 0.002), w(0, 0, -1);
  EXPECT_FALSE(advance_against_solids<3>(settings(5e4), solids.view(), y, w, kMass, kDensity,
                                         kGravity, 0.01, room)
                   .overflowed);
}

TEST(SolidContactStepper, AStiffLayerStopsAndHoldsAFallingParticle) {
  // Ks = 5e4 N/m on 0.002 m solids: at rest the springs carry the weight m g.
  for (const Real x0 : {0.051, 0.05, 0.0513}) {
    const Drop d = drop(5e4, 0.002, x0, 0.05, 100);
    EXPECT_FALSE(d.crossed_plane) << x0;
    EXPECT_GT(d.x.z(), 0) << x0;
    EXPECT_LT(d.v.norm(), 1e-3) << x0;
    EXPECT_NEAR(d.last_force.z(), 9.81 * kMass, 1e-3 * 9.81 * kMass) << x0;
  }
}

TEST(SolidContactStepper, ASoftLayerLetsTheParticleThrough) {
  // Ks = 1e-3 N/m stores far less than the 1/2 m v^2 = 1.05e-4 J of the impact.
  const Drop d = drop(1e-3, 0.002, 0.051, 0.05, 10);
  EXPECT_TRUE(d.crossed_plane);
}

// The same particle resting on the layer, with the layer and the particle both carried along
// at `drift`: the layer as a body's particles, moving through the step (gather_moving).
Vec3 rest_on_layer_moving_at(const Vec3& drift, Vec3& x) {
  ParticleSet<3> particles;
  std::vector<Real> solid_spacing;
  const Real spacing = 0.002;
  for (int i = 0; i < 50; ++i) {
    for (int j = 0; j < 50; ++j) {
      particles.add(Vec3((i + 0.5) * spacing, (j + 0.5) * spacing, 0), drift, 2800, 1,
                    ParticleKind::kBody);
      particles.body_point.back() = i * 50 + j;
      solid_spacing.push_back(spacing);
    }
  }
  std::vector<std::uint32_t> bodies(particles.size());
  std::vector<Vec3> start(particles.size());
  for (std::size_t k = 0; k < particles.size(); ++k) {
    bodies[k] = static_cast<std::uint32_t>(k);
    start[k] = particles.position[k];
    particles.position[k] += 0.01 * drift;  // where the body's advance put it
  }
  SolidParticles<3> solids;
  solids.gather(particles, solid_spacing, kFluidSpacing, 0.0055);
  solids.gather_moving(particles, solid_spacing, bodies, start, 0.01);
  EXPECT_EQ(solids.fixed_count, 0u);
  EXPECT_NEAR((solids.velocity[7] - drift).norm(), 0, 1e-12);
  EXPECT_EQ(start[7], particles.position[7]);  // the next drift starts from here
  std::vector<SolidCandidate> scratch;
  Vec3 v = Vec3(0, 0, -0.3) + drift;
  const SolidContactSettings<3> s = settings(5e4);
  advance_against_solids<3>(s, solids.view(), x, v, kMass, kDensity, kGravity, 0.01, scratch);
  return v;
}

TEST(SolidContactStepper, MovingSolidsAreGalileanInvariant) {
  // Galilean invariance: carried along at (0.2, 0, 0.1) m/s with the layer, the particle
  // lands and rests as it does on a layer at rest, displaced by that velocity times the step.
  // (Not to round-off: the sub-steps' lengths follow the particle's own speed, so the two
  // runs take different ones; 1e-5 m/s is 3e-5 of the impact speed.)
  Vec3 x_still(0.051, 0.05, 0.0035), x_moving = x_still;
  const Vec3 drift(0.2, 0, 0.1);
  const Vec3 v_still = rest_on_layer_moving_at(Vec3::Zero(), x_still);
  const Vec3 v_moving = rest_on_layer_moving_at(drift, x_moving);
  EXPECT_NEAR((x_moving - x_still - 0.01 * drift).norm(), 0, 1e-9);
  EXPECT_NEAR((v_moving - v_still - drift).norm(), 0, 1e-5);
  EXPECT_GT(x_still.z(), 0.0012);  // it did land on the layer (reach 2.65 mm) and stay
}

}  // namespace
}  // namespace sluice
