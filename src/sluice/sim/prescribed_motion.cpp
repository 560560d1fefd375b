#include "sluice/sim/prescribed_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "sluice/core/smooth_ramp.hpp"

namespace sluice {

Eigen::Quaterniond rotation_from_angles(const Vec3& angles) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angles[2], Vec3::UnitZ()) *
                            Eigen::AngleAxisd(angles[1], Vec3::UnitY()) *
                            Eigen::AngleAxisd(angles[0], Vec3::UnitX()));
}

Vec3 angular_velocity_from_rates(const Vec3& angles, const Vec3& rates) {
  // R = Rz(c) Ry(b) Rx(a): each angle turns about its axis as carried by the turns after it.
  const Eigen::AngleAxisd about_z(angles[2], Vec3::UnitZ());
  const Eigen::AngleAxisd about_y(angles[1], Vec3::UnitY());
  return rates[2] * Vec3::UnitZ() + rates[1] * (about_z * Vec3::UnitY()) +
         rates[0] * (about_z * (about_y * Vec3::UnitX()));
}

namespace {

// A paddle's pose: a piston moved along x by the signal's displacement; a flap turned about y
// (positive turns carry its top towards +x) through atan(X / d), X the displacement at the
// still water line, d the hinge's depth below it.
ShapePose paddle_pose(const io::BodyConfig& body, double time, const PaddleCorrection& correction) {
  const io::WavemakerConfig& w = body.prescribed.wavemaker;
  const double x = w.signal.displacement(time) + correction.displacement;
  const double v = w.signal.velocity(time) + correction.velocity;
  const Eigen::Quaterniond rest = rotation_from_angles(body.rotation);
  if (w.paddle == io::PaddleKind::kPiston) {
    return {body.position + x * Vec3::UnitX(), rest, v * Vec3::UnitX(), Vec3::Zero()};
  }
  const double d = w.hinge_depth;
  const Vec3 hinge(body.position[0], body.position[1], w.still_water - d);
  const Eigen::AngleAxisd turn(std::atan2(x, d), Vec3::UnitY());
  const Vec3 arm = turn * (body.position - hinge);
  const Vec3 omega = (v * d / (d * d + x * x)) * Vec3::UnitY();
  return {hinge + arm, Eigen::Quaterniond(turn) * rest, omega.cross(arm), omega};
}

}  // namespace

ShapePose prescribed_pose(const io::BodyConfig& body, double time,
                          const PaddleCorrection& correction) {
  const io::PrescribedConfig& p = body.prescribed;
  if (p.kind == io::PrescribedKind::kWavemaker) return paddle_pose(body, time, correction);
  Vec3 position = body.position, angles = body.rotation;
  Vec3 velocity = Vec3::Zero(), rates = Vec3::Zero();
  switch (p.kind) {
    case io::PrescribedKind::kConstantVelocity: {
      // A smooth start, (1 - cos(pi t / T)) / 2 of the speed, spares the fluid the pressure
      // wave of an impulsive one; `travelled` is its integral, the time spent at full speed.
      const SmoothRamp ramp = smooth_ramp(time, p.ramp_time);
      const double share = ramp.share, travelled = ramp.integral;
      velocity = share * body.velocity;
      rates = share * body.angular_velocity;
      position += travelled * body.velocity;
      angles += travelled * body.angular_velocity;
      break;
    }
    case io::PrescribedKind::kSinusoid: {
      const double omega = 2 * std::numbers::pi * p.frequency;
      const double s = std::sin(omega * time + p.phase) - std::sin(p.phase);
      const double c = omega * std::cos(omega * time + p.phase);
      position += s * p.amplitude;
      angles += s * p.rotation_amplitude;
      velocity = c * p.amplitude;
      rates = c * p.rotation_amplitude;
      break;
    }
    case io::PrescribedKind::kTable: {
      const auto& rows = p.table;
      const auto after =
          std::upper_bound(rows.begin(), rows.end(), time,
                           [](double t, const io::PoseSample& r) { return t < r.time; });
      if (after == rows.begin() || after == rows.end()) {
        const io::PoseSample& held = after == rows.begin() ? rows.front() : rows.back();
        position = held.position;
        angles = held.rotation;
      } else {
        const io::PoseSample& a = *(after - 1);
        const io::PoseSample& b = *after;
        const double span = b.time - a.time, w = (time - a.time) / span;
        position = (1 - w) * a.position + w * b.position;
        angles = (1 - w) * a.rotation + w * b.rotation;
        velocity = (b.position - a.position) / span;
        rates = (b.rotation - a.rotation) / span;
      }
      break;
    }
    case io::PrescribedKind::kWavemaker:
      break;  // paddle_pose
  }
  return {position, rotation_from_angles(angles), velocity,
          angular_velocity_from_rates(angles, rates)};
}

}  // namespace sluice
