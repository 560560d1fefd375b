// The friction cone of a contact and its projection (Anitescu & Tasora 2010): the impulse
// (gamma_n, gamma_u, gamma_v) of a contact lies in the cone |(gamma_u, gamma_v)| <= mu gamma_n;
// with cohesion c >= 0 the cone's apex moves to gamma_n = -c, so that the contact can pull
// with up to c.
#pragma once

#include <Eigen/Geometry>
#include <cmath>

#include "sluice/core/host_device.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

// Projects (n, u, v) onto the cone of friction mu and cohesion c, in place: the nearest point
// of the cone (Euclidean).
SLUICE_HOST_DEVICE inline void project_on_cone(Real& n, Real& u, Real& v, Real mu, Real c) {
  Real shifted = n + c;
  if (mu <= 0) {
    n = std::max<Real>(shifted, 0) - c;
    u = v = 0;
    return;
  }
  const Real t = std::sqrt(u * u + v * v);
  if (t <= mu * shifted) return;  // inside
  if (mu * t <= -shifted) {       // in the polar cone: the apex
    n = -c;
    u = v = 0;
    return;
  }
  const Real on_surface = (mu * t + shifted) / (mu * mu + 1);
  const Real scale = mu * on_surface / t;
  n = on_surface - c;
  u *= scale;
  v *= scale;
}

// Two unit tangents completing a unit normal to a right-handed frame, a fixed function of
// the normal (so that a contact's tangential impulses keep their meaning from step to step).
inline void tangent_basis(const Vec3& n, Vec3& u, Vec3& v) {
  // The axis least aligned with n gives a well-conditioned first tangent.
  const Vec3 a = std::abs(n.x()) < 0.6 ? Vec3::UnitX() : Vec3::UnitY();
  u = (a - a.dot(n) * n).normalized();
  v = n.cross(u);
}

}  // namespace sluice
