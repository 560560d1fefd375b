// Reading bodies from a case file, and prescribed motion: documented defaults, units (degrees
// in, radians kept), 2D conventions, and the pose table.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "sluice/core/errors.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/sim/prescribed_motion.hpp"
#include "sluice/waves/linear_waves.hpp"
#include "sluice/waves/paddle_transfer.hpp"
#include "support/scratch_dir.hpp"

namespace sluice::io {
namespace {

constexpr double kDegree = std::numbers::pi / 180;

std::string case_3d(const std::string& body) {
  return "dimension: 3\nspacing: 0.05\ndomain: {min: [0, 0, 0], max: [1, 1, 1]}\n"
         "end_time: 1\noutput_interval: 0.1\nbodies:\n  - " +
         body + "\n";
}

TEST(BodyReader, ReadsABoxWithDefaults) {
  const CaseConfig c = parse_case(
      case_3d("{shape: box, size: [0.1, 0.2, 0.3], density: 800, position: [0.5, 0.5, 0.5], "
              "rotation_deg: [0, 0, 90]}"),
      "t.yaml");
  ASSERT_EQ(c.bodies.size(), 1u);
  const BodyConfig& b = c.bodies[0];
  EXPECT_EQ(b.name, "body0");
  EXPECT_EQ(b.shape, BodyShape::kBox);
  EXPECT_EQ(b.size, Vec3(0.1, 0.2, 0.3));
  EXPECT_DOUBLE_EQ(b.density, 800);
  EXPECT_DOUBLE_EQ(b.mass, 0);
  EXPECT_NEAR(b.rotation[2], std::numbers::pi / 2, 1e-15);
  EXPECT_EQ(b.motion, BodyMotion::kFree);
  EXPECT_FALSE(b.locked_translation[1]);
  const ContactMaterial fallback;
  EXPECT_DOUBLE_EQ(b.material.young, fallback.young);
  EXPECT_DOUBLE_EQ(b.material.restitution, fallback.restitution);
  EXPECT_FALSE(c.has_fluid());
  EXPECT_DOUBLE_EQ(c.contact.distance, 0.05);  // the spacing
  EXPECT_DOUBLE_EQ(c.body_interval, c.probe_interval);
}

TEST(BodyReader, TwoDimensionalBodiesTurnAboutY) {
  const CaseConfig c = parse_case(
      "dimension: 2\nspacing: 0.05\ndomain: {min: [0, 0], max: [1, 1]}\nend_time: 1\n"
      "output_interval: 0.1\nbodies:\n  - {shape: sphere, radius: 0.1, mass: 2, "
      "position: [0.5, 0.5], rotation_deg: 30, angular_velocity: 2, locked: [x]}\n",
      "t.yaml");
  const BodyConfig& b = c.bodies[0];
  EXPECT_EQ(b.position, Vec3(0.5, 0, 0.5));
  EXPECT_NEAR(b.rotation[1], 30 * kDegree, 1e-15);
  EXPECT_EQ(b.angular_velocity, Vec3(0, 2, 0));
  // The plane's own locks plus the one asked for.
  EXPECT_TRUE(b.locked_translation[0]);
  EXPECT_TRUE(b.locked_translation[1]);
  EXPECT_FALSE(b.locked_translation[2]);
  EXPECT_TRUE(b.locked_rotation[0]);
  EXPECT_FALSE(b.locked_rotation[1]);
  EXPECT_TRUE(b.locked_rotation[2]);
}

TEST(BodyReader, WallMaterialDefaultsToStiffAndPermissive) {
  const CaseConfig c = parse_case(
      case_3d("{shape: sphere, radius: 0.1, density: 1000, position: [0.5, 0.5, 0.5]}") +
          "walls:\n  - {type: tank, min: [0, 0, 0], max: [1, 1, 1], material: {friction: 0.2}}\n",
      "t.yaml");
  EXPECT_DOUBLE_EQ(c.walls[0].material.friction, 0.2);
  EXPECT_DOUBLE_EQ(c.walls[0].material.restitution, 1.0);
  EXPECT_GT(c.walls[0].material.young, 1e10);
}

class PoseTable : public ::testing::Test {
 protected:
  CaseConfig read_with_table(const std::string& table) {
    std::ofstream(dir_ / "motion.csv") << table;
    std::ofstream(dir_ / "case.yaml") << case_3d(
        "{shape: box, size: [0.1, 0.1, 0.1], density: 800, position: [0.5, 0.5, 0.5], "
        "motion: prescribed, prescribed: {type: table, file: motion.csv}}");
    return read_case((dir_ / "case.yaml").string());
  }
  test_support::ScratchDir dir_{"sluice_pose_table"};
};

TEST_F(PoseTable, InterpolatesAndHoldsAtTheEnds) {
  const CaseConfig c = read_with_table("time, x, rz_deg\n0, 0.2, 0\n1, 0.4, 90\n");
  const BodyConfig& b = c.bodies[0];
  ASSERT_EQ(b.prescribed.table.size(), 2u);
  const ShapePose middle = prescribed_pose(b, 0.25);
  EXPECT_NEAR(middle.position[0], 0.25, 1e-15);
  EXPECT_NEAR(middle.position[2], 0.0, 1e-15);  // a column left out is zero
  EXPECT_NEAR(middle.velocity[0], 0.2, 1e-15);
  EXPECT_NEAR(middle.angular_velocity[2], 90 * kDegree, 1e-12);
  const Vec3 turned = middle.orientation * Vec3::UnitX();
  EXPECT_NEAR(std::atan2(turned[1], turned[0]), 22.5 * kDegree, 1e-12);
  const ShapePose after = prescribed_pose(b, 5.0);
  EXPECT_NEAR(after.position[0], 0.4, 1e-15);
  EXPECT_EQ(after.velocity, Vec3::Zero());
}

TEST_F(PoseTable, UnsortedTimesNameTheRow) {
  try {
    read_with_table("time,x\n0,0\n0.5,1\n0.5,2\n");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "bodies[0].prescribed.file");
    EXPECT_NE(std::string(e.what()).find("line 4: time 0.5 does not come after 0.5"),
              std::string::npos)
        << e.what();
  }
}

TEST(PrescribedMotion, SinusoidStartsAtThePoseWithItsDerivative) {
  BodyConfig b;
  b.position = Vec3(1, 2, 3);
  b.motion = BodyMotion::kPrescribed;
  b.prescribed.kind = PrescribedKind::kSinusoid;
  b.prescribed.amplitude = Vec3(0.1, 0, 0);
  b.prescribed.frequency = 2;
  b.prescribed.phase = 0.3;
  EXPECT_EQ(prescribed_pose(b, 0).position, b.position);
  const double t = 0.1, omega = 4 * std::numbers::pi;
  const ShapePose p = prescribed_pose(b, t);
  EXPECT_NEAR(p.position[0], 1 + 0.1 * (std::sin(omega * t + 0.3) - std::sin(0.3)), 1e-15);
  EXPECT_NEAR(p.velocity[0], 0.1 * omega * std::cos(omega * t + 0.3), 1e-14);
}

TEST(PrescribedMotion, AngularVelocityIsThatOfTheTurningAngles) {
  // Three angles changing at once: the angular velocity must be the one that carries the
  // orientation along, here checked against a central difference of the orientation.
  const Vec3 angles(0.3, -0.5, 1.1), rates(0.7, 0.2, -0.4);
  // omega = 2 q' q^-1, with q' from a central difference of the quaternion's components.
  const double h = 1e-5;
  Eigen::Quaterniond rate;
  rate.coeffs() = (rotation_from_angles(angles + h * rates).coeffs() -
                   rotation_from_angles(angles - h * rates).coeffs()) /
                  (2 * h);
  const Vec3 expected = 2 * (rate * rotation_from_angles(angles).conjugate()).vec();
  const Vec3 omega = angular_velocity_from_rates(angles, rates);
  for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(omega[axis], expected[axis], 1e-8) << axis;
  EXPECT_GT((omega - rates).norm(), 0.1);  // not the rates themselves
}

TEST(PrescribedMotion, ConstantVelocityMovesAndTurns) {
  BodyConfig b;
  b.motion = BodyMotion::kPrescribed;
  b.velocity = Vec3(1, 0, 0);
  b.angular_velocity = Vec3(0, 0, std::numbers::pi);
  const ShapePose p = prescribed_pose(b, 0.5);
  EXPECT_NEAR(p.position[0], 0.5, 1e-15);
  const Vec3 turned = p.orientation * Vec3::UnitX();
  EXPECT_NEAR(turned[1], 1.0, 1e-15);  // a quarter turn about z
}

// A 2D case of one paddle centred at (0.15, height) over a floor at `floor`, with the
// wavemaker's keys `keys`.
std::string paddle_case(double floor, double height, const std::string& keys) {
  return "dimension: 2\nspacing: 0.05\ndomain: {min: [0, " + std::to_string(floor) +
         "], max: [4, 0.8]}\nend_time: 1\noutput_interval: 0.1\nbodies:\n"
         "  - {shape: box, size: [0.1, 0.8], density: 1000, position: [0.15, " +
         std::to_string(height) + "], motion: prescribed, prescribed: {type: wavemaker, " + keys +
         "}}\n";
}

// A flap read from a case: its signal is the wave's height over Biésel's transfer function
// for a flap hinged where the case says, and its top's crossing of the still water line
// follows the signal's displacement while the body moves as one rigid piece.
TEST(PrescribedMotion, FlapWavemakerTurnsAboutItsHingeByTheStroke) {
  const CaseConfig c =
      parse_case(paddle_case(-0.1, 0.3,
                             "paddle: flap, water_depth: 0.5, hinge_depth: 0.4, height: 0.03, "
                             "period: 1.2, ramp_time: 1.2"),
                 "t.yaml");
  const BodyConfig& b = c.bodies[0];
  const WavemakerConfig& w = b.prescribed.wavemaker;
  ASSERT_EQ(b.prescribed.kind, PrescribedKind::kWavemaker);
  EXPECT_EQ(w.paddle, PaddleKind::kFlap);
  EXPECT_DOUBLE_EQ(w.still_water, 0.4);  // the floor at -0.1
  const double omega = 2 * std::numbers::pi / 1.2;
  const double k = waves::wavenumber(omega, 0.5, 9.81);
  ASSERT_EQ(w.signal.parts.size(), 1u);
  EXPECT_NEAR(w.signal.parts[0].amplitude, 0.015 / waves::height_over_stroke(k, 0.5, 0.4), 1e-15);
  EXPECT_EQ(prescribed_pose(b, 0).position, b.position);
  for (double t : {0.4, 1.5, 2.2}) {
    const ShapePose p = prescribed_pose(b, t);
    // The flap's centre line, hinge (0.15, 0) to the turned up direction, crosses z = 0.4 at
    // the hinge's x plus the displacement.
    const Vec3 up = p.orientation * Vec3::UnitZ();
    const Vec3 hinge(0.15, 0, 0.0);
    EXPECT_NEAR((p.position - hinge).cross(up).norm(), 0, 1e-14) << "the hinge stays on it";
    EXPECT_NEAR(hinge[0] + up[0] / up[2] * 0.4, 0.15 + w.signal.displacement(t), 1e-14);
    // A corner's velocity, v + omega x r, is the rate of its position.
    const Vec3 corner(0.05, 0, 0.4);
    auto at = [&](double time) {
      const ShapePose q = prescribed_pose(b, time);
      return Vec3(q.position + q.orientation * corner);
    };
    const double h = 1e-6;
    const Vec3 rate = (at(t + h) - at(t - h)) / (2 * h);
    const Vec3 velocity = p.velocity + p.angular_velocity.cross(p.orientation * corner);
    EXPECT_NEAR((velocity - rate).norm(), 0, 1e-7) << "t " << t;
  }
}

TEST(PrescribedMotion, PistonWavemakerMovesAlongXWithMadsensSecondHarmonic) {
  const CaseConfig c = parse_case(
      paddle_case(0, 0.4, "water_depth: 0.5, height: 0.04, period: 2.0, order: 2"), "t.yaml");
  const BodyConfig& b = c.bodies[0];
  const WavemakerConfig& w = b.prescribed.wavemaker;
  EXPECT_EQ(w.paddle, PaddleKind::kPiston);
  EXPECT_DOUBLE_EQ(w.signal.ramp_time, 4.0);  // two periods
  ASSERT_EQ(w.signal.parts.size(), 2u);
  const double k = waves::wavenumber(std::numbers::pi, 0.5, 9.81);
  EXPECT_NEAR(w.signal.parts[1].amplitude, waves::madsen_second_harmonic(0.04, k, 0.5), 1e-15);
  EXPECT_DOUBLE_EQ(w.signal.parts[1].omega, 2 * std::numbers::pi);
  const ShapePose p = prescribed_pose(b, 5.3);
  EXPECT_NEAR(p.position[0], 0.15 + w.signal.displacement(5.3), 1e-15);
  EXPECT_EQ(p.position[2], 0.4);
  EXPECT_NEAR(p.velocity[0], w.signal.velocity(5.3), 1e-15);
  EXPECT_EQ(p.angular_velocity, Vec3::Zero());
}

}  // namespace
}  // namespace sluice::io
