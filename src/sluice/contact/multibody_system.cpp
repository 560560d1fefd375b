#include "sluice/contact/multibody_system.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "sluice/rigid/rigid_integrator.hpp"

namespace sluice {

namespace {

constexpr int kDirections = 6;  // contacts of one body pair are told apart by +-x, +-y, +-z

int direction_of(const Vec3& n) {
  int axis = 0;
  n.cwiseAbs().maxCoeff(&axis);
  return 2 * axis + (n[axis] < 0 ? 1 : 0);
}

// How far the box lies in front of the plane: the smallest signed distance of its corners.
double height_above(const Bounds& box, const HalfSpace& plane) {
  const Vec3 centre = 0.5 * (box.min + box.max), half = 0.5 * (box.max - box.min);
  return (centre - plane.point).dot(plane.normal) - half.dot(plane.normal.cwiseAbs());
}

}  // namespace

MultibodySystem::MultibodySystem(double contact_distance, Vec3 gravity, double substep_fraction)
    : contact_distance_(contact_distance), gravity_(gravity), substep_fraction_(substep_fraction) {}

std::size_t MultibodySystem::add(ContactBody body) {
  bodies_.push_back(std::move(body));
  contact_force_.assign(bodies_.size(), Vec3::Zero());
  contact_torque_.assign(bodies_.size(), Vec3::Zero());
  return bodies_.size() - 1;
}

const ContactPair& MultibodySystem::pair(std::size_t a, std::size_t b) {
  const std::uint64_t key = a * bodies_.size() + b;
  auto found = pairs_.find(key);
  if (found != pairs_.end()) return found->second;
  const ContactBody& A = bodies_[a];
  const ContactBody& B = bodies_[b];
  return pairs_
      .emplace(key, make_contact_pair(A.material, A.fixed ? 0 : A.state.mass, A.contact_radius,
                                      B.material, B.fixed ? 0 : B.state.mass, B.contact_radius))
      .first->second;
}

bool MultibodySystem::in_reach(std::size_t a, std::size_t b, double margin) const {
  const Bounds& box_a = surfaces_[a].bounds();
  const Bounds& box_b = surfaces_[b].bounds();
  if (!box_a.overlaps(box_b, margin)) return false;
  if (bodies_[a].half_space) return height_above(box_b, *bodies_[a].half_space) <= margin;
  if (bodies_[b].half_space) return height_above(box_a, *bodies_[b].half_space) <= margin;
  return true;
}

void MultibodySystem::place_surfaces() {
  surfaces_.resize(bodies_.size());
  for (std::size_t b = 0; b < bodies_.size(); ++b)
    surfaces_[b].update(bodies_[b], 2 * contact_distance_);
}

std::vector<MultibodySystem::Contact> MultibodySystem::find_contacts() {
  place_surfaces();
  const std::size_t n = bodies_.size();
  const double reach2 = contact_distance_ * contact_distance_;
  std::vector<Contact> contacts;
  std::map<std::uint64_t, std::size_t> index;  // (a, b, direction) -> contact
  std::vector<std::uint32_t> near_a, near_b;
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      if (bodies_[a].fixed && bodies_[b].fixed) continue;
      const WorldSurface& surface_a = surfaces_[a];
      const WorldSurface& surface_b = surfaces_[b];
      if (!in_reach(a, b, contact_distance_)) continue;
      surface_a.near(surface_b.bounds(), contact_distance_, near_a);
      const auto& points_a = surface_a.points();
      const auto& points_b = surface_b.points();
      const Vec3 centres = (bodies_[b].state.position - bodies_[a].state.position).normalized();
      // The particles of b within the contact distance of a particle of a: from b's own grid
      // when b never moves, else from a grid of b's particles near a, built for this pair.
      const PointGrid* grid_b = &surface_b.grid();
      if (grid_b->empty()) {
        surface_b.near(surface_a.bounds(), contact_distance_, near_b);
        pair_grid_.build(points_b, &near_b, 2 * contact_distance_);
        grid_b = &pair_grid_;
      }
      const Vec3 reach = Vec3::Constant(contact_distance_);
      for (std::uint32_t k : near_a) {
        // Each particle of a meets the nearest particle of b whose face faces its own: one
        // pair per particle, so a face's pairs do not multiply or thin out as the two lattices
        // slide over each other.
        const Vec3& n_k = surface_a.normals()[k];
        std::uint32_t l = 0;
        double nearest = reach2;
        grid_b->for_each_in_cells(points_a[k] - reach, points_a[k] + reach, [&](std::uint32_t m) {
          const double d2 = (points_b[m] - points_a[k]).squaredNorm();
          if (d2 >= nearest || n_k.dot(surface_b.normals()[m]) > -0.3) return;
          nearest = d2;
          l = m;
        });
        if (nearest >= reach2) continue;
        const Vec3 d = points_b[l] - points_a[k];
        const Vec3& n_l = surface_b.normals()[l];
        // From a into b. Between flat faces, the mean of the two face normals (seed 000);
        // against one flat face, that face's normal, so its plane gives the gap whatever the
        // lateral offset of the pair; between two curved bodies, the line of centres.
        const bool flat_a = bodies_[a].flat_faces, flat_b = bodies_[b].flat_faces;
        const Vec3 n_c = flat_a && flat_b ? Vec3((n_k - n_l).normalized())
                         : flat_b         ? Vec3(-n_l)
                         : flat_a         ? n_k
                                          : centres;
        double overlap = -d.dot(n_c);  // minus the gap between the faces
        // A sphere's surface is known exactly: against another sphere or a flat face, the
        // overlap follows from its centre rather than from the nearest sampled points.
        const ContactBody& A = bodies_[a];
        const ContactBody& B = bodies_[b];
        if (A.spherical && B.spherical) {
          overlap =
              A.contact_radius + B.contact_radius - (B.state.position - A.state.position).norm();
        } else if (A.spherical && flat_b) {
          overlap = A.contact_radius - (A.state.position - points_b[l]).dot(n_l);
        } else if (B.spherical && flat_a) {
          overlap = B.contact_radius - (B.state.position - points_a[k]).dot(n_k);
        }
        if (overlap <= 0) continue;
        const std::uint64_t key = (a * n + b) * kDirections + direction_of(n_c);
        auto [slot, fresh] = index.emplace(key, contacts.size());
        if (fresh) {
          contacts.emplace_back();
          contacts.back().a = a;
          contacts.back().b = b;
        }
        Contact& c = contacts[slot->second];
        const double area = std::min(bodies_[a].surface_area[k], bodies_[b].surface_area[l]);
        const double w = overlap * std::sqrt(overlap) * area;
        // Where the pair's force acts: on a sphere, its true contact point, a radius less half
        // the overlap from its centre (the sampled pairs lie around it, and their mean nearer
        // the centre would make it roll on a smaller radius); else half the overlap beyond a's
        // particle. Not midway to b's particle: that point jumps as the
        // nearest particle of b changes while the faces slide, and all of a face's pairs jump
        // together, shaking the body at the lattice-crossing frequency.
        const Vec3 acts_at =
            A.spherical   ? Vec3(A.state.position + (A.contact_radius - 0.5 * overlap) * n_c)
            : B.spherical ? Vec3(B.state.position - (B.contact_radius - 0.5 * overlap) * n_c)
                          : Vec3(points_a[k] + 0.5 * overlap * n_c);
        c.overlap = std::max(c.overlap, overlap);
        c.area += area;
        c.weight += w;
        c.point += w * acts_at;
        c.normal += w * n_c;
        c.pairs.push_back({acts_at, overlap, area});
      }
    }
  }
  for (Contact& c : contacts) {
    c.point /= c.weight;
    c.normal.normalize();
  }
  return contacts;
}

void MultibodySystem::apply_contacts(double dt) {
  std::fill(contact_force_.begin(), contact_force_.end(), Vec3::Zero());
  std::fill(contact_torque_.begin(), contact_torque_.end(), Vec3::Zero());
  elastic_energy_ = 0;
  deepest_overlap_ = 0;
  std::map<std::uint64_t, Vec3> still_touching;
  const std::size_t n = bodies_.size();
  for (const Contact& c : find_contacts()) {
    const ContactBody& A = bodies_[c.a];
    const ContactBody& B = bodies_[c.b];
    const ContactPair& law = pair(c.a, c.b);
    // On a curved body the force acts on the line through its centre along the normal (a
    // sphere's contact force passes through its centre; its pairs already act at its true
    // contact point, see find_contacts); on a flat face, where it is applied. The relative
    // velocity is taken where the force acts: a rolling sphere's surface at a sampled point
    // beside the true contact would add a normal velocity of omega times the offset and make
    // the dashpot push and pull.
    auto lever = [&](const ContactBody& body, const Vec3& point) -> Vec3 {
      const Vec3 arm = point - body.state.position;
      return body.flat_faces ? arm : Vec3(arm.dot(c.normal) * c.normal);
    };
    auto relative_velocity = [&](const Vec3& point) -> Vec3 {
      auto velocity = [&](const ContactBody& body) {
        return body.state.velocity_at(body.state.position + lever(body, point));
      };
      return velocity(B) - velocity(A);
    };
    auto add = [&](const Vec3& force, const Vec3& point) {
      contact_force_[c.b] += force;
      contact_torque_[c.b] += lever(B, point).cross(force);
      contact_force_[c.a] -= force;
      contact_torque_[c.a] -= lever(A, point).cross(force);
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
    const std::uint64_t key = (c.a * n + c.b) * kDirections + direction_of(c.normal);
    Vec3 tangential = Vec3::Zero();
    if (auto found = tangential_.find(key); found != tangential_.end()) tangential = found->second;
    const Vec3 relative = relative_velocity(c.point);
    const Vec3 v_t = relative - relative.dot(c.normal) * c.normal;
    bool sliding = false;
    add(mindlin_tangential_force(law, overlap, c.normal, v_t, normal_force, tangential, dt, elastic,
                                 sliding),
        c.point);
    still_touching[key] = tangential;
    elastic_energy_ += elastic;
    deepest_overlap_ = std::max(deepest_overlap_, c.overlap);
  }
  deepest_overlap_ever_ = std::max(deepest_overlap_ever_, deepest_overlap_);
  tangential_.swap(still_touching);  // a contact that ended forgets its history
}

double MultibodySystem::solid_step(double dt) {
  place_surfaces();
  const std::size_t n = bodies_.size();
  double step = dt;
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      const ContactBody& A = bodies_[a];
      const ContactBody& B = bodies_[b];
      if (A.fixed && B.fixed) continue;
      // In reach within this step: bounding boxes closer than the way the bodies can travel.
      const double approach =
          (B.state.velocity - A.state.velocity).norm() +
          (A.state.angular_velocity().norm() + B.state.angular_velocity().norm()) *
              (surfaces_[a].bounds().max - surfaces_[a].bounds().min).norm();
      if (!in_reach(a, b, approach * dt + contact_distance_)) continue;
      const ContactPair& p = pair(a, b);
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
      step = std::min(step, substep_fraction_ * period);
    }
  }
  return step;
}

int MultibodySystem::advance(double dt, const std::vector<Vec3>& force,
                             const std::vector<Vec3>& torque) {
  const int substeps = static_cast<int>(std::ceil(dt / solid_step(dt) - 1e-9));
  const double h = dt / substeps;
  const std::size_t n = bodies_.size();
  if (substeps_ == 0) apply_contacts(0);
  auto total_force = [&](std::size_t b) {
    Vec3 f = bodies_[b].state.mass * gravity_ + contact_force_[b];
    if (b < force.size()) f += force[b];
    return f;
  };
  auto total_torque = [&](std::size_t b) {
    Vec3 t = contact_torque_[b];
    if (b < torque.size()) t += torque[b];
    return t;
  };
  for (int s = 0; s < substeps; ++s) {
    for (std::size_t b = 0; b < n; ++b) {
      if (bodies_[b].prescribed) bodies_[b].prescribed(time_ + (s + 1) * h, bodies_[b].state);
      if (bodies_[b].fixed) continue;
      kick(bodies_[b].state, total_force(b), total_torque(b), 0.5 * h);
      drift(bodies_[b].state, h);
    }
    // The dashpots see the velocities predicted to the end of the sub-step (with the forces
    // of the last evaluation), not the half-step ones, which would lag by h/2.
    std::vector<RigidBody> half(n);
    for (std::size_t b = 0; b < n; ++b) {
      half[b] = bodies_[b].state;
      if (!bodies_[b].fixed) kick(bodies_[b].state, total_force(b), total_torque(b), 0.5 * h);
    }
    apply_contacts(h);
    for (std::size_t b = 0; b < n; ++b) bodies_[b].state = half[b];
    for (std::size_t b = 0; b < n; ++b) {
      if (!bodies_[b].fixed) kick(bodies_[b].state, total_force(b), total_torque(b), 0.5 * h);
    }
    ++substeps_;
  }
  time_ += dt;
  return substeps;
}

MultibodyEnergy MultibodySystem::energy() const {
  MultibodyEnergy e;
  for (const ContactBody& body : bodies_) {
    if (body.fixed) continue;
    e.kinetic += body.state.kinetic_energy();
    e.potential -= body.state.mass * gravity_.dot(body.state.position);
  }
  e.elastic = elastic_energy_;
  return e;
}

}  // namespace sluice
