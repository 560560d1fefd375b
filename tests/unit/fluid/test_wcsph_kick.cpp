// The second half kick of wcsph's kick-drift-kick (wcsph_loop_bodies.hpp): velocity and density
// from their half-step values and the rates, the density no lower than the equation of state's
// inverse gives, and the pressure of that density.
#include <gtest/gtest.h>

#include "sluice/fluid/wcsph/wcsph_loop_bodies.hpp"

namespace sluice {
namespace {

struct OneParticle {
  Real position[2] = {0, 0}, velocity[2] = {0, 0}, half_velocity[2] = {1, 2};
  Real acceleration[2] = {10, -20}, density = 0, half_density = 1000, density_rate = 0;
  Real pressure = 0, mass = 1;
  std::int32_t kind = 0, body_point = -1;
  WcsphFields<2> fields() {
    WcsphFields<2> f;
    f.size = 1;
    f.position = position;
    f.velocity = velocity;
    f.density = &density;
    f.pressure = &pressure;
    f.mass = &mass;
    f.kind = &kind;
    f.body_point = &body_point;
    f.acceleration = acceleration;
    f.density_rate = &density_rate;
    f.half_velocity = half_velocity;
    f.half_density = &half_density;
    return f;
  }
};

TEST(WcsphKick, SecondHalfKickTakesTheRates) {
  OneParticle p;
  p.density_rate = 2000;
  const TaitEquation eos(1000, 30, 7);
  wcsph_second_half_kick(p.fields(), 0, 1e-3, eos);
  EXPECT_DOUBLE_EQ(p.velocity[0], 1 + 1e-3 * 10);
  EXPECT_DOUBLE_EQ(p.velocity[1], 2 - 1e-3 * 20);
  EXPECT_DOUBLE_EQ(p.density, 1002);
  EXPECT_DOUBLE_EQ(p.pressure, eos.pressure(1002));
}

// A particle whose neighbours fly apart loses density at whatever rate they give it; it stops
// at the inverse's bound, and never reaches zero, where its volume m / rho in its neighbours'
// sums would blow up. Above the bound the density is the rates', clamped tension or not.
TEST(WcsphKick, DensityStopsAtTheEquationOfStatesBound) {
  for (const bool clamp : {false, true}) {
    const TaitEquation eos(1000, 30, 7, clamp);
    OneParticle p;
    p.density_rate = -2e6;  // would reach -1000 kg/m^3 in the half step
    wcsph_second_half_kick(p.fields(), 0, 1e-3, eos);
    EXPECT_EQ(p.density, eos.lowest_density) << clamp;
    EXPECT_GT(p.density, 130.0) << clamp;
    EXPECT_EQ(p.pressure, eos.pressure(eos.lowest_density)) << clamp;
    OneParticle q;
    q.density_rate = -2000;
    wcsph_second_half_kick(q.fields(), 0, 1e-3, eos);
    EXPECT_DOUBLE_EQ(q.density, 998.0) << clamp;
    EXPECT_EQ(q.pressure, eos.pressure(q.density)) << clamp;
  }
}

}  // namespace
}  // namespace sluice
