// Where a point fixed in a body stands and how it moves, in plain arrays: the host places its
// body points with these (BodyPoints) and a device run places them there from the bodies'
// kinematics alone, in the same arithmetic, so that both give the same bits.
#pragma once

#include "sluice/core/host_device.hpp"

namespace sluice {

// A body's kinematics as reals: its centre (3), the quaternion x, y, z, w from its principal
// frame to the world (4), velocity (3), angular velocity (3), acceleration (3) and angular
// acceleration (3).
inline constexpr int kBodyMotionReals = 19;

SLUICE_HOST_DEVICE inline void cross_product(const double* a, const double* b, double* out) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

// out = q v q^-1 for a unit quaternion q = (x, y, z, w): v + 2 w (u x v) + u x (2 u x v).
SLUICE_HOST_DEVICE inline void rotate_by(const double* q, const double* v, double* out) {
  double t[3], ut[3];
  cross_product(q, v, t);
  for (int a = 0; a < 3; ++a) t[a] *= 2;
  cross_product(q, t, ut);
  for (int a = 0; a < 3; ++a) out[a] = v[a] + q[3] * t[a] + ut[a];
}

// The point at `local` in the principal frame of the body whose kinematics `body` holds.
SLUICE_HOST_DEVICE SLUICE_ONE_HOST_COPY inline void rigid_point_position(const double* body,
                                                                         const double* local,
                                                                         double* out) {
  double r[3];
  rotate_by(body + 3, local, r);
  for (int a = 0; a < 3; ++a) out[a] = body[a] + r[a];
}

// Its velocity, v + omega x r.
SLUICE_HOST_DEVICE SLUICE_ONE_HOST_COPY inline void rigid_point_velocity(const double* body,
                                                                         const double* local,
                                                                         double* out) {
  double r[3], spin[3];
  rotate_by(body + 3, local, r);
  cross_product(body + 10, r, spin);
  for (int a = 0; a < 3; ++a) out[a] = body[7 + a] + spin[a];
}

// Its acceleration, a + alpha x r + omega x (omega x r).
SLUICE_HOST_DEVICE SLUICE_ONE_HOST_COPY inline void rigid_point_acceleration(const double* body,
                                                                             const double* local,
                                                                             double* out) {
  double r[3], tangential[3], spin[3], centripetal[3];
  rotate_by(body + 3, local, r);
  cross_product(body + 16, r, tangential);
  cross_product(body + 10, r, spin);
  cross_product(body + 10, spin, centripetal);
  for (int a = 0; a < 3; ++a) out[a] = body[13 + a] + tangential[a] + centripetal[a];
}

}  // namespace sluice
