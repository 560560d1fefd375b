#include "sluice/contact/penalty_contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sluice {

const ContactPair& PenaltyContactSolver::law(std::size_t a, std::size_t b,
                                             const std::vector<SystemBody>& bodies,
                                             const std::vector<ContactShape>& shapes) {
  const std::uint64_t key = (std::uint64_t(a) << 32) | b;
  auto found = laws_.find(key);
  if (found != laws_.end()) return found->second;
  const SystemBody& A = bodies[a];
  const SystemBody& B = bodies[b];
  return laws_
      .emplace(key,
               make_contact_pair(shapes[a].material, A.fixed ? 0 : A.state.mass,
                                 shapes[a].contact_radius, shapes[b].material,
                                 B.fixed ? 0 : B.state.mass, shapes[b].contact_radius, damping_))
      .first->second;
}

void PenaltyContactSolver::solve(ContactSet& contacts, const std::vector<SystemBody>& bodies,
                                 const std::vector<ContactShape>& shapes, double dt,
                                 std::vector<Vec3>& force, std::vector<Vec3>& torque) {
  elastic_energy_ = 0;
  deepest_overlap_ = 0;
  for (Contact& c : contacts.contacts()) {
    const RigidBody& A = bodies[c.a].state;
    const RigidBody& B = bodies[c.b].state;
    const ContactShape& shape_a = shapes[c.a];
    const ContactShape& shape_b = shapes[c.b];
    const ContactPair& law = this->law(c.a, c.b, bodies, shapes);
    // On a curved body the force acts on the line through its centre along the normal (a
    // sphere's contact force passes through its centre; its pairs already act at its true
    // contact point, see the narrow phase); on a flat face, where it is applied. The relative
    // velocity is taken where the force acts: a rolling sphere's surface at a sampled point
    // beside the true contact would add a normal velocity of omega times the offset and make
    // the dashpot push and pull.
    auto lever = [&](const RigidBody& body, const ContactShape& shape, const Vec3& point) {
      const Vec3 arm = point - body.position;
      return shape.flat_faces ? arm : Vec3(arm.dot(c.normal) * c.normal);
    };
    auto relative_velocity = [&](const Vec3& point) -> Vec3 {
      auto velocity = [&](const RigidBody& body, const ContactShape& shape) {
        return body.velocity_at(body.position + lever(body, shape, point));
      };
      return velocity(B, shape_b) - velocity(A, shape_a);
    };
    auto add = [&](const Vec3& f, const Vec3& point) {
      force[c.b] += f;
      torque[c.b] += lever(B, shape_b, point).cross(f);
      force[c.a] -= f;
      torque[c.a] -= lever(A, shape_a, point).cross(f);
    };
    // Normal: each pair carries the bodies' Hertz law at its own overlap and normal velocity,
    // times its share of the pairs' area. A face pressed evenly gives the law of the bodies
    // whatever the number of pairs. A tilt moves the force to the deeper side without raising
    // the total at first order. The law at the deepest pair would raise it: friction pitching
    // a sliding block then raises the normal force, so the friction and the pitch, and the
    // block hops at its contact frequency (C3's block: the force swung between 0.05 and 2.2
    // times the weight; now within about 10 %).
    double normal_force = 0, elastic = 0;
    for (const ParticlePair& p : c.pairs) {
      const double v_n = relative_velocity(p.point).dot(c.normal);
      const double fraction = p.area / c.area;
      const double share = fraction * hertz_normal_force(law, p.overlap, v_n);
      add(share * c.normal, p.point);
      normal_force += share;
      elastic +=
          fraction * 0.4 * law.normal_stiffness * p.overlap * p.overlap * std::sqrt(p.overlap);
    }
    // The overlap whose law gives the same spring force, for the tangential stiffness.
    const double overlap = std::pow(c.weight / c.area, 2.0 / 3.0);
    // Tangential: one Mindlin spring per contact, at the weighted contact point.
    const Vec3 relative = relative_velocity(c.point);
    const Vec3 v_t = relative - relative.dot(c.normal) * c.normal;
    bool sliding = false;
    add(mindlin_tangential_force(law, overlap, c.normal, v_t, normal_force, c.tangential, dt,
                                 elastic, sliding),
        c.point);
    elastic_energy_ += elastic;
    deepest_overlap_ = std::max(deepest_overlap_, c.overlap);
  }
  deepest_overlap_ever_ = std::max(deepest_overlap_ever_, deepest_overlap_);
}

double PenaltyContactSolver::pair_step(std::size_t a, std::size_t b, double approach,
                                       const std::vector<SystemBody>& bodies,
                                       const std::vector<ContactShape>& shapes) {
  const ContactPair& p = law(a, b, bodies, shapes);
  // The stiffest the contact gets: Hertz's peak overlap for this approach speed, or the
  // overlap that carries the body's weight, whichever is deeper.
  const double v = std::max(approach, 1e-3);
  const double impact = std::pow(
      15 * p.effective_mass * v * v / (16 * p.effective_young * std::sqrt(p.effective_radius)),
      0.4);
  const double weight =
      std::pow(p.effective_mass * gravity_.norm() / p.normal_stiffness, 2.0 / 3.0);
  const double overlap = std::max({impact, weight, deepest_overlap_});
  const double stiffness = 1.5 * p.normal_stiffness * std::sqrt(overlap);
  const double period = std::numbers::pi * std::sqrt(p.effective_mass / stiffness);
  return substep_fraction_ * period;
}

}  // namespace sluice
