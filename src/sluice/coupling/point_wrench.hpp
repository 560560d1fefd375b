// The wrench of one point force, in plain arrays: the host sums a body's points with it
// (BodyPoints::loads) and a device run sums them where its forces are, in the same order and
// the same arithmetic, so that both give the same bits.
#pragma once

#include "sluice/core/host_device.hpp"

namespace sluice {

// Adds the force f at point p and its moment about `centre`, (p - centre) x f, to wrench[0..3)
// and wrench[3..6).
SLUICE_HOST_DEVICE inline void add_point_wrench(const double* p, const double* centre,
                                                const double* f, double* wrench) {
  const double r0 = p[0] - centre[0], r1 = p[1] - centre[1], r2 = p[2] - centre[2];
  wrench[0] += f[0];
  wrench[1] += f[1];
  wrench[2] += f[2];
  wrench[3] += r1 * f[2] - r2 * f[1];
  wrench[4] += r2 * f[0] - r0 * f[2];
  wrench[5] += r0 * f[1] - r1 * f[0];
}

// The wrench of the points [first, end) of one body, each a run of 3 reals in `position` and
// `force`, in the points' order, into wrench[0..6).
SLUICE_HOST_DEVICE SLUICE_ONE_HOST_COPY inline void sum_point_wrenches(
    const double* position, const double* force, unsigned long first, unsigned long end,
    const double* centre, double* wrench) {
  for (int a = 0; a < 6; ++a) wrench[a] = 0;
  for (unsigned long k = first; k < end; ++k) {
    add_point_wrench(position + 3 * k, centre, force + 3 * k, wrench);
  }
}

}  // namespace sluice
