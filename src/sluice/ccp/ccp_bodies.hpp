// The bodies of a cone complementarity problem (velocity-level contact and joints, Anitescu &
// Tasora 2010): what the impulses act on. Each body has its velocity and angular velocity as
// predicted without the impulses, its inverse mass (0: fixed, moved by nothing), an inverse
// inertia in the world frame (a tensor for the first bodies, the rigid system's; a scalar for
// the rest, a granular fluid's spheres) and the degrees of freedom it is locked in.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "sluice/core/host_device.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

using Mat3 = Eigen::Matrix3d;

// Locks: bits 0-2 translation along x, y, z; bits 3-5 rotation about x, y, z (world axes).
inline constexpr std::uint8_t kLockPlanar = 0b101'010;  // a 2D case in the x-z plane

// What M^-1 reads of the bodies (CcpBodies below), over plain arrays, for loop bodies that run
// on the host's threads or a device's.
struct CcpBodiesView {
  const Real* inverse_mass = nullptr;
  const Mat3* inverse_inertia = nullptr;  // the first tensor_count bodies'
  std::size_t tensor_count = 0;
  const Real* inverse_inertia_scalar = nullptr;
  const std::uint8_t* locks = nullptr;

  // The change of body b's velocities from an impulse p and an angular impulse l about its
  // centre: M^-1 (p, l), zero along its locked degrees of freedom.
  SLUICE_HOST_DEVICE void velocity_change(std::size_t b, const Vec3& p, const Vec3& l, Vec3& dv,
                                          Vec3& dw) const {
    dv = inverse_mass[b] * p;
    dw = b < tensor_count ? Vec3(inverse_inertia[b] * l) : Vec3(inverse_inertia_scalar[b] * l);
    const std::uint8_t bits = locks[b];
    if (bits == 0) return;
    // By multiplication, not per component: writing single components of a vector that is
    // then read whole stalls the processor's store forwarding (measured: a third of the
    // granular model's time).
    dv = dv.cwiseProduct(free_axes(bits & 7));
    dw = dw.cwiseProduct(free_axes(bits >> 3));
  }

  // 1 along the axes the three bits leave free, 0 along the locked ones.
  SLUICE_HOST_DEVICE static Vec3 free_axes(unsigned bits) {
    return Vec3(bits & 1 ? 0.0 : 1.0, bits & 2 ? 0.0 : 1.0, bits & 4 ? 0.0 : 1.0);
  }
};

struct CcpBodies {
  std::vector<Vec3> velocity, angular_velocity;
  std::vector<Real> inverse_mass;
  std::vector<Mat3> inverse_inertia;         // world frame, for the first tensor_count() bodies
  std::vector<Real> inverse_inertia_scalar;  // for the others (a sphere's 1 / I)
  std::vector<std::uint8_t> locks;

  std::size_t size() const { return velocity.size(); }
  std::size_t tensor_count() const { return inverse_inertia.size(); }

  void clear() {
    velocity.clear();
    angular_velocity.clear();
    inverse_mass.clear();
    inverse_inertia.clear();
    inverse_inertia_scalar.clear();
    locks.clear();
  }

  // Adds a body with a full inverse inertia; these come before every scalar one.
  std::size_t add(const Vec3& v, const Vec3& w, Real inverse_m, const Mat3& inverse_i,
                  std::uint8_t lock_bits) {
    if (inverse_inertia.size() != velocity.size())
      throw std::logic_error("CcpBodies: a tensor body after a scalar one");
    inverse_inertia.push_back(inverse_i);
    return push(v, w, inverse_m, 0, lock_bits);
  }
  // Adds a body with a scalar inverse inertia (a sphere).
  std::size_t add(const Vec3& v, const Vec3& w, Real inverse_m, Real inverse_i,
                  std::uint8_t lock_bits) {
    return push(v, w, inverse_m, inverse_i, lock_bits);
  }

  CcpBodiesView view() const {
    return {inverse_mass.data(), inverse_inertia.data(), inverse_inertia.size(),
            inverse_inertia_scalar.data(), locks.data()};
  }
  // CcpBodiesView::velocity_change.
  void velocity_change(std::size_t b, const Vec3& p, const Vec3& l, Vec3& dv, Vec3& dw) const {
    view().velocity_change(b, p, l, dv, dw);
  }

 private:
  std::size_t push(const Vec3& v, const Vec3& w, Real inverse_m, Real inverse_i,
                   std::uint8_t lock_bits) {
    velocity.push_back(v);
    angular_velocity.push_back(w);
    inverse_mass.push_back(inverse_m);
    inverse_inertia_scalar.push_back(inverse_i);
    locks.push_back(lock_bits);
    return velocity.size() - 1;
  }
};

// Velocities of every body of a problem: the predicted ones plus what the impulses add.
struct BodyVelocities {
  std::vector<Vec3> linear, angular;
};

}  // namespace sluice
