// Active absorption at a wave paddle (sim/paddle_absorber): where it reads the water, the
// velocity it adds, and the displacement that velocity carries.
#include <gtest/gtest.h>

#include "sluice/sim/paddle_absorber.hpp"

namespace sluice {
namespace {

// Water at a given height everywhere; remembers where it was read.
class LevelWater final : public FluidObservation {
 public:
  double height = 0.5;
  mutable Vec3 read_at = Vec3::Constant(-1);
  FluidView view() const override { return {}; }
  double pressure_at(const Vec3&) const override { return 0; }
  double water_height_at(const Vec3& gauge) const override {
    read_at = gauge;
    return height;
  }
  double surge_front(int) const override { return 0; }
  FluidSize size() const override { return {}; }
  FluidEnergy energy() const override { return {}; }
};

// A piston 0.1 m thick, its face at x = 0.2, over water 0.5 m deep on a floor at z = 0,
// signal still (no parts): only the absorption moves it.
io::BodyConfig still_piston(double gain) {
  io::BodyConfig paddle;
  paddle.size = Vec3(0.1, 0, 0.8);
  paddle.position = Vec3(0.15, 0, 0.4);
  paddle.motion = io::BodyMotion::kPrescribed;
  paddle.prescribed.kind = io::PrescribedKind::kWavemaker;
  io::WavemakerConfig& w = paddle.prescribed.wavemaker;
  w.water_depth = w.still_water = 0.5;
  w.period = 2.0;
  w.active_absorption = true;
  w.absorption_gain = gain;
  return paddle;
}

TEST(PaddleAbsorber, StillWaterAtTheTargetLeavesThePaddleWhereItIs) {
  const io::BodyConfig paddle = still_piston(3.0);
  PaddleAbsorber absorber(paddle, 0.0, 0.04);
  LevelWater water;
  absorber.measure(0.0, water);
  EXPECT_DOUBLE_EQ(absorber.at(0.5).displacement, 0.0);
  EXPECT_DOUBLE_EQ(absorber.at(0.5).velocity, 0.0);
  EXPECT_DOUBLE_EQ(water.read_at[0], 0.2 + 0.04);  // the gap before the face
}

TEST(PaddleAbsorber, WaterAboveItsMeanMovesThePaddleBackAtTheGain) {
  const double gain = 3.0, gap = 0.04, dt = 0.01, ten_periods = 20.0;
  const io::BodyConfig paddle = still_piston(gain);
  PaddleAbsorber absorber(paddle, 0.0, gap);
  LevelWater water;
  absorber.measure(0.0, water);
  water.height = 0.51;  // a crest 1 cm high arriving; the mean level moves dt / 10 T of it
  absorber.measure(dt, water);
  double mean = 0.01 * dt / ten_periods;
  EXPECT_NEAR(absorber.at(2 * dt).velocity, -gain * (0.01 - mean), 1e-15);
  const double moved = -gain * (0.01 - mean) * dt;
  EXPECT_NEAR(absorber.at(2 * dt).displacement, moved, 1e-15);
  // The crest gone: the mean level's own lag and the leak back to the mean position remain;
  // the displacement goes on from where it was, and the water is read before the moved face.
  water.height = 0.5;
  absorber.measure(2 * dt, water);
  mean -= mean * dt / ten_periods;
  EXPECT_NEAR(absorber.at(2 * dt).displacement, moved, 1e-15);
  EXPECT_NEAR(absorber.at(2 * dt).velocity, gain * mean - moved / ten_periods, 1e-15);
  EXPECT_NEAR(water.read_at[0], 0.2 + moved + gap, 1e-15);
}

TEST(PaddleAbsorber, ASteadyErrorOfTheReadingDoesNotMoveIt) {
  const io::BodyConfig paddle = still_piston(3.0);
  PaddleAbsorber absorber(paddle, 0.0, 0.04);
  LevelWater water;
  water.height = 0.503;  // the gauge reads 3 mm high from the start
  for (int step = 0; step < 1000; ++step) absorber.measure(0.01 * step, water);
  EXPECT_EQ(absorber.at(10.0).displacement, 0.0);
  EXPECT_EQ(absorber.at(10.0).velocity, 0.0);
}

TEST(PaddleAbsorber, ItsStateComesBackFromACheckpoint) {
  const io::BodyConfig paddle = still_piston(3.0);
  PaddleAbsorber written(paddle, 0.0, 0.04), read(paddle, 0.0, 0.04);
  LevelWater water;
  written.measure(0.1, water);
  water.height = 0.52;
  written.measure(0.3, water);
  StateArchive out;
  out(written);
  StateArchive in(out.bytes());
  in(read);
  in.finish();
  EXPECT_EQ(read.at(0.4).displacement, written.at(0.4).displacement);
  EXPECT_EQ(read.at(0.4).velocity, written.at(0.4).velocity);
}

}  // namespace
}  // namespace sluice
