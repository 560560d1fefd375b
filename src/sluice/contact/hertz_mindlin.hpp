// The penalty contact law of seed 000 (Amaro Junior, Cheng & Osello 2019): a Hertz spring with
// a dashpot in the normal direction, a Mindlin spring on the accumulated tangential
// displacement with a dashpot, capped by Coulomb friction.
#pragma once

#include <map>

#include "sluice/contact/contact_material.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

// Everything the law needs for one pair of bodies. Combination rule (docs/contact.md):
// 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2, 1/G* = (2 - nu1)/G1 + (2 - nu2)/G2, 1/m* and 1/R*
// sum the inverses (a wall has infinite mass and radius), e and mu are the smaller of the two.
struct ContactPair {
  double effective_mass = 0;
  double effective_radius = 0;
  double effective_young = 0;
  double effective_shear = 0;
  double restitution = 1;
  double friction = 0;
  double normal_stiffness = 0;          // K_n = 4/3 E* sqrt(R*)
  double normal_damping = 0;            // eta: damping force = -eta delta^(1/4) v_n (reproduces e)
  double tangential_damping_ratio = 0;  // 2 sqrt(5/6) |beta| (Tsuji et al. 1992)
};

// The dimensionless damping gamma for which x'' = -x^(3/2) - gamma x^(1/4) x', x(0) = 0,
// x'(0) = 1 leaves contact (the force returns to zero) with speed e: found by bisection on a
// fine integration, so the law reproduces e exactly rather than by a fitted formula.
double hertz_damping_for_restitution(double restitution);

// hertz_damping_for_restitution, remembered: the bisection integrates the oscillator some 60
// times, and a run meets the same few restitutions over and over. One per contact solver.
class HertzDampingTable {
 public:
  double gamma(double restitution);

 private:
  std::map<double, double> known_;
};

// mass or radius <= 0 or infinite means "a wall" (infinite).
ContactPair make_contact_pair(const ContactMaterial& a, double mass_a, double radius_a,
                              const ContactMaterial& b, double mass_b, double radius_b,
                              HertzDampingTable& damping);

struct ContactForce {
  Vec3 force = Vec3::Zero();  // on the first body, at the contact point
  double normal = 0;          // |F_n| >= 0
  double elastic_energy = 0;  // 2/5 K_n delta^(5/2) + |delta_t|^2 S_t / 2
  bool sliding = false;
};

// The normal force |F_n| >= 0 for overlap delta > 0 and normal relative velocity v_n (< 0 while
// approaching): Hertz spring plus the dashpot, clamped at zero.
double hertz_normal_force(const ContactPair& pair, double overlap, double normal_velocity);

// The tangential force for a contact carrying `normal_force`, with the tangential relative
// velocity v_t; updates the accumulated displacement `tangential` (see below). Adds the spring's
// energy to `elastic_energy` and sets `sliding`.
Vec3 mindlin_tangential_force(const ContactPair& pair, double overlap, const Vec3& normal,
                              const Vec3& tangential_velocity, double normal_force,
                              Vec3& tangential, double dt, double& elastic_energy, bool& sliding);

// Force on body 1 from body 2 for overlap delta > 0 along `normal` (unit, pointing from body 2
// into body 1), with the relative velocity v1 - v2 at the contact point. `tangential` is the
// accumulated tangential displacement of this contact: turned into the current tangent plane,
// advanced by dt, and reset to the Coulomb limit while sliding.
ContactForce hertz_mindlin_force(const ContactPair& pair, double overlap, const Vec3& normal,
                                 const Vec3& relative_velocity, Vec3& tangential, double dt);

}  // namespace sluice
