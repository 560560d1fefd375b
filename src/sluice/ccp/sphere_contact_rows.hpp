// The rows of a granular fluid's sphere contacts (sphere_contacts.hpp) as loop bodies over
// plain arrays, each a function of one contact's or one sphere's index, so that the host's
// threads run them on the group's vectors and a device run on its copy: the rows' velocities,
// the impulses gathered by each sphere, the projection onto the cones, the diagonal.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "sluice/ccp/ccp_bodies.hpp"
#include "sluice/ccp/cone.hpp"
#include "sluice/core/host_device.hpp"

namespace sluice {

inline constexpr std::uint32_t kSphereWorld = 0xFFFFFFFF;  // the "sphere" a wall contact has

struct SphereContact {
  std::uint32_t a = kSphereWorld, b = 0;  // problem bodies; a may be kSphereWorld (a wall)
  std::uint32_t owner = 0;                // identity it is kept under: the smaller sphere's
  std::uint32_t partner = 0;              // the other sphere's identity, or a wall's code
  Vec3 normal = Vec3::UnitZ();            // from a into b
  Real radius_a = 0, radius_b = 0;        // from each centre to the contact point, along n
  Real target = 0;                        // the least normal velocity [m/s]
};

// One of a sphere's contacts: 2 c + side (side 0: it is a; 1: it is b), and the direction its
// normal impulse pushes it (minus the normal for a), in single precision: the gather of the
// frictionless case reads nothing else (a sixth of a contact's record).
struct SphereContactEntry {
  float push[3];
  std::uint32_t contact_side;
};

// The contacts and what every row reads: k rows a contact (1, 3 or 6), each contact's two
// tangents with friction (at 2 c and 2 c + 1).
struct SphereRows {
  const SphereContact* contacts;
  const Vec3* tangents;
  std::size_t k;
};

// out[c k + r] = row r's velocity of contact c for body velocities (linear, angular), less its
// target for the normal row.
struct SphereRowVelocities {
  SphereRows rows;
  const Vec3* linear;
  const Vec3* angular;
  Real* out;
  SLUICE_HOST_DEVICE void operator()(std::size_t c) const {
    const std::size_t k = rows.k;
    const SphereContact& contact = rows.contacts[c];
    const Vec3& n = contact.normal;
    Vec3 va = Vec3::Zero(), wa = Vec3::Zero();
    if (contact.a != kSphereWorld) {
      va = linear[contact.a];
      wa = angular[contact.a];
    }
    const Vec3& vb = linear[contact.b];
    out[c * k] = n.dot(vb - va) - contact.target;
    if (k == 1) return;
    // The contact point's velocity on each side: v + w x (arm), arm_a = r_a n, arm_b = -r_b n.
    const Vec3 slip =
        vb - contact.radius_b * angular[contact.b].cross(n) - va - contact.radius_a * wa.cross(n);
    const Vec3& t1 = rows.tangents[2 * c];
    const Vec3& t2 = rows.tangents[2 * c + 1];
    out[c * k + 1] = t1.dot(slip);
    out[c * k + 2] = t2.dot(slip);
    if (k == 3) return;
    const Vec3 turn = angular[contact.b] - wa;
    out[c * k + 3] = t1.dot(turn);
    out[c * k + 4] = t2.dot(turn);
    out[c * k + 5] = n.dot(turn);
  }
};

// Sphere s (problem body first + s) gathers its contacts' impulses gamma, in its list's order,
// and takes M^-1 of their sum: one thread a sphere, so the sum's order is fixed. Frictionless
// contacts (one row each) push along their normals alone: SphereNormalImpulses.
struct SphereImpulses {
  SphereRows rows;
  const std::uint32_t* list_offsets;
  const SphereContactEntry* list;
  const Real* gamma;
  std::size_t first;
  CcpBodiesView bodies;
  Vec3* linear;
  Vec3* angular;
  SLUICE_HOST_DEVICE void operator()(std::size_t s) const {
    const std::size_t k = rows.k;
    Vec3 p = Vec3::Zero(), l = Vec3::Zero();
    for (std::uint32_t e = list_offsets[s]; e < list_offsets[s + 1]; ++e) {
      const std::size_t c = list[e].contact_side / 2;
      const bool is_b = list[e].contact_side & 1;
      const SphereContact& contact = rows.contacts[c];
      const Vec3& n = contact.normal;
      Vec3 impulse = gamma[c * k] * n;  // on b; minus it on a
      if (k >= 3) {
        const Vec3& t1 = rows.tangents[2 * c];
        const Vec3& t2 = rows.tangents[2 * c + 1];
        const Vec3 tangential = gamma[c * k + 1] * t1 + gamma[c * k + 2] * t2;
        impulse += tangential;
        // arm x impulse: b's arm is -r_b n, a's is r_a n (and a takes minus the impulse).
        l += is_b ? Vec3(-contact.radius_b * n.cross(tangential))
                  : Vec3(-contact.radius_a * n.cross(tangential));
        if (k == 6) {
          const Vec3 torque = gamma[c * k + 3] * t1 + gamma[c * k + 4] * t2 + gamma[c * k + 5] * n;
          l += is_b ? torque : Vec3(-torque);
        }
      }
      p += is_b ? impulse : Vec3(-impulse);
    }
    Vec3 dv, dw;
    bodies.velocity_change(first + s, p, l, dv, dw);
    linear[first + s] += dv;
    angular[first + s] += dw;
  }
};
struct SphereNormalImpulses {
  const std::uint32_t* list_offsets;
  const SphereContactEntry* list;
  const Real* gamma;
  std::size_t first;
  CcpBodiesView bodies;
  Vec3* linear;
  SLUICE_HOST_DEVICE void operator()(std::size_t s) const {
    Real px = 0, py = 0, pz = 0;
    for (std::uint32_t e = list_offsets[s]; e < list_offsets[s + 1]; ++e) {
      const SphereContactEntry& entry = list[e];
      const Real g = gamma[entry.contact_side / 2];
      px += g * entry.push[0];
      py += g * entry.push[1];
      pz += g * entry.push[2];
    }
    Vec3 dv, dw;
    bodies.velocity_change(first + s, Vec3(px, py, pz), Vec3::Zero(), dv, dw);
    linear[first + s] += dv;
  }
};

// Contact c's impulses onto its set: with friction mu and cohesion c0 its cone, with rolling
// friction mu_r the rolling and spinning torques within mu_r r of the normal impulse just
// projected (Tasora & Anitescu 2013), r the pair's reduced radius.
struct SphereProjection {
  SphereRows rows;
  Real friction, cohesion, rolling_friction;
  Real* gamma;
  SLUICE_HOST_DEVICE void operator()(std::size_t c) const {
    const std::size_t k = rows.k;
    if (k == 1) {
      gamma[c] = std::max(gamma[c] + cohesion, Real(0)) - cohesion;
      return;
    }
    project_on_cone(gamma[c * k], gamma[c * k + 1], gamma[c * k + 2], friction, cohesion);
    if (k == 3) return;
    const SphereContact& contact = rows.contacts[c];
    const Real r = contact.radius_a > 0
                       ? contact.radius_a * contact.radius_b / (contact.radius_a + contact.radius_b)
                       : contact.radius_b;
    const Real limit = rolling_friction * r * std::max<Real>(gamma[c * k] + cohesion, 0);
    const Real rolling = std::hypot(gamma[c * k + 3], gamma[c * k + 4]);
    if (rolling > limit) {
      gamma[c * k + 3] *= limit / rolling;
      gamma[c * k + 4] *= limit / rolling;
    }
    gamma[c * k + 5] = std::clamp(gamma[c * k + 5], -limit, limit);
  }
};

// Contact c's rows' share of the diagonal of D^T M^-1 D: the spheres' inverse masses for the
// normal and tangent rows (one value a cone), their inverse inertias for the torques' rows.
struct SphereDiagonal {
  SphereRows rows;
  CcpBodiesView bodies;
  Real* out;
  SLUICE_HOST_DEVICE void operator()(std::size_t c) const {
    const std::size_t k = rows.k;
    const SphereContact& contact = rows.contacts[c];
    const bool two = contact.a != kSphereWorld;
    const Real d = (two ? bodies.inverse_mass[contact.a] : 0) + bodies.inverse_mass[contact.b];
    for (std::size_t r = 0; r < (k < 3 ? k : 3); ++r) out[c * k + r] = d;
    // The torques' rows turn the spheres only.
    const Real turn = (two ? bodies.inverse_inertia_scalar[contact.a] : 0) +
                      bodies.inverse_inertia_scalar[contact.b];
    for (std::size_t r = 3; r < k; ++r) out[c * k + r] = turn;
  }
};

}  // namespace sluice
