// The boundary force of seed 002 on a fluid particle from one solid particle (equations 8-11,
// after Amada 2006 and Kristof et al. 2009): a penalty spring-dashpot that keeps the fluid out,
//   f_np = (Ks d - Kd (v - v_b) . n) n,
// and a no-slip traction -mu_w (v - v_b) V_b lap W_visc(|r - r_b|).
//
// Each solid particle is a sphere of radius L_b / 2 (L_b its spacing) and each fluid particle
// one of radius l0 / 2; they touch at the reach (L_b + l0) / 2, and d is how far inside it the
// fluid particle is, along the normal n from the solid particle to the fluid one. The normal
// is taken from where the fluid particle was at the start of the step: a particle that
// went past the solid particle's centre within the step (its path came within the reach)
// keeps the normal of the side it came from, so that d is larger than the reach and the spring
// pushes it back rather than on through. The spring never pulls:
// the force is zero when the dashpot would make it attractive.
//
// The paper weighs the traction by L_b^2, the area of a solid particle on a surface; with the
// volume kernel's Laplacian (1/m^5 in 3D) that leaves a force density one length short, so
// sluice weighs it by the solid particle's volume L_b^D: then it is the SPH viscosity term of
// a neighbour moving with the solid, which is what the paper's no-slip force stands for.
#pragma once

#include <algorithm>

#include "sluice/core/host_device.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

struct PenaltyLaw {
  Real stiffness = 0;  // Ks [N/m]
  Real damping = 0;    // Kd [N s/m]
};

template <int D>
struct PenaltyContact {
  Vec<D> force = Vec<D>::Zero();   // f_np [N]
  Vec<D> normal = Vec<D>::Zero();  // n, from the solid particle towards the fluid one
  Real depth = 0;                  // d [m]; 0 when not in contact
  bool crossed = false;            // the particle passed the solid particle's centre this step
};

// f_np on a fluid particle now at x, at x_previous at the start of the step, moving at v, from
// a solid particle at xb moving at vb, touching at `reach`.
template <int D>
SLUICE_HOST_DEVICE PenaltyContact<D> penalty_contact(const PenaltyLaw& law, const Vec<D>& x,
                                                     const Vec<D>& x_previous, const Vec<D>& v,
                                                     const Vec<D>& xb, const Vec<D>& vb,
                                                     Real reach) {
  PenaltyContact<D> c;
  const Vec<D> from_previous = x_previous - xb;
  const Real previous_distance = from_previous.norm();
  const Vec<D> offset = x - xb;
  Vec<D> normal;
  if (previous_distance > 0 && offset.dot(from_previous) < 0) {
    // Past the centre from where the step started: crossed, unless the path stayed outside.
    if (previous_distance >= reach) {
      const Vec<D> path = x - x_previous;
      const Real along =
          std::clamp(-from_previous.dot(path) / path.squaredNorm(), Real(0), Real(1));
      if ((from_previous + along * path).norm() >= reach) return c;
    }
    normal = from_previous / previous_distance;
    c.crossed = true;
  } else {
    const Real distance = offset.norm();
    if (distance >= reach || distance <= 0) return c;
    normal = offset / distance;
  }
  c.depth = reach - offset.dot(normal);
  if (c.depth <= 0) return {};
  c.normal = normal;
  const Real magnitude = law.stiffness * c.depth - law.damping * (v - vb).dot(normal);
  c.force = std::max<Real>(magnitude, 0) * normal;
  return c;
}

}  // namespace sluice
