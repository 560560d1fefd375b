#include "sluice/contact/narrow_phase.hpp"

#include <algorithm>
#include <cmath>

namespace sluice {

void NarrowPhase::find(std::size_t a, std::size_t b, const std::vector<SystemBody>& bodies,
                       const std::vector<ContactShape>& shapes,
                       const std::vector<WorldSurface>& surfaces, ContactSet& contacts,
                       double least_overlap) {
  const double reach2 = distance_ * distance_;
  const WorldSurface& surface_a = surfaces[a];
  const WorldSurface& surface_b = surfaces[b];
  surface_a.near(surface_b.bounds(), distance_, near_a_);
  const auto& points_a = surface_a.points();
  const auto& points_b = surface_b.points();
  const Vec3 centres = (bodies[b].state.position - bodies[a].state.position).normalized();
  // The particles of b within the contact distance of a particle of a: from b's own grid
  // when b never moves, else from a grid of b's particles near a, built for this pair.
  const PointGrid* grid_b = &surface_b.grid();
  if (grid_b->empty()) {
    surface_b.near(surface_a.bounds(), distance_, near_b_);
    pair_grid_.build(points_b, &near_b_, 2 * distance_);
    grid_b = &pair_grid_;
  }
  const Vec3 reach = Vec3::Constant(distance_);
  for (std::uint32_t k : near_a_) {
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
    const bool flat_a = shapes[a].flat_faces, flat_b = shapes[b].flat_faces;
    const Vec3 n_c = flat_a && flat_b ? Vec3((n_k - n_l).normalized())
                     : flat_b         ? Vec3(-n_l)
                     : flat_a         ? n_k
                                      : centres;
    double overlap = -d.dot(n_c);  // minus the gap between the faces
    // A sphere's surface is known exactly: against another sphere or a flat face, the
    // overlap follows from its centre rather than from the nearest sampled points.
    const ContactShape& A = shapes[a];
    const ContactShape& B = shapes[b];
    const RigidBody& state_a = bodies[a].state;
    const RigidBody& state_b = bodies[b].state;
    if (A.spherical && B.spherical) {
      overlap = A.contact_radius + B.contact_radius - (state_b.position - state_a.position).norm();
    } else if (A.spherical && flat_b) {
      overlap = A.contact_radius - (state_a.position - points_b[l]).dot(n_l);
    } else if (B.spherical && flat_a) {
      overlap = B.contact_radius - (state_b.position - points_a[k]).dot(n_k);
    }
    if (overlap <= least_overlap) continue;
    const double area = std::min(A.surface_area[k], B.surface_area[l]);
    // Where the pair's force acts: on a sphere, its true contact point, a radius less half
    // the overlap from its centre (the sampled pairs lie around it, and their mean nearer
    // the centre would make it roll on a smaller radius); else half the overlap beyond a's
    // particle. Not midway to b's particle: that point jumps as the
    // nearest particle of b changes while the faces slide, and all of a face's pairs jump
    // together, shaking the body at the lattice-crossing frequency.
    const Vec3 acts_at =
        A.spherical   ? Vec3(state_a.position + (A.contact_radius - 0.5 * overlap) * n_c)
        : B.spherical ? Vec3(state_b.position - (B.contact_radius - 0.5 * overlap) * n_c)
                      : Vec3(points_a[k] + 0.5 * overlap * n_c);
    contacts.add(a, b, {acts_at, n_c, overlap, area});
  }
}

}  // namespace sluice
