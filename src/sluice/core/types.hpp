// Basic numeric types shared by every part of sluice.
#pragma once

#include <Eigen/Core>
#include <cstdint>

#include "sluice/core/host_device.hpp"

namespace sluice {

using Real = double;

// A point or vector in D dimensions. 2D cases live in the x-z plane: component 0 is x and
// component 1 is z (up).
template <int D>
using Vec = Eigen::Matrix<Real, D, 1>;

using Vec3 = Eigen::Matrix<Real, 3, 1>;

// A body's velocity (linear, then angular) or an impulse on it (force, then moment), and the
// 6 x 6 maps between them (world).
using Vec6 = Eigen::Matrix<Real, 6, 1>;
using Mat6 = Eigen::Matrix<Real, 6, 6>;

// Index of the "up" axis (against gravity in every shipped case) in a D-dimensional vector.
template <int D>
inline constexpr int kUpAxis = D - 1;

// Maps a D-dimensional vector into 3D space (2D: x-z plane at y = 0).
template <int D>
SLUICE_HOST_DEVICE Vec3 to_3d(const Vec<D>& v) {
  if constexpr (D == 3) {
    return v;
  } else {
    return Vec3(v[0], 0.0, v[1]);
  }
}

// Maps a 3D vector into the model's space (2D: drops y).
template <int D>
SLUICE_HOST_DEVICE Vec<D> from_3d(const Vec3& v) {
  if constexpr (D == 3) {
    return v;
  } else {
    return Vec<D>(v[0], v[2]);
  }
}

}  // namespace sluice
