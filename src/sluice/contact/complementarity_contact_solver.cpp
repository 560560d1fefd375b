#include "sluice/contact/complementarity_contact_solver.hpp"

#include <algorithm>

#include "sluice/ccp/contact_rows.hpp"

namespace sluice {

void ComplementarityContactSolver::add_cones(const ContactSet& contacts,
                                             const std::vector<SystemBody>& bodies,
                                             const std::vector<ContactShape>& shapes, double h,
                                             double recovery_speed, RowGroup& rows) {
  for (const Contact& c : contacts.contacts()) {
    const Vec3& xa = bodies[c.a].state.position;
    const Vec3& xb = bodies[c.b].state.position;
    const Real mu = std::min(shapes[c.a].material.friction, shapes[c.b].material.friction);
    for (std::size_t k = 0; k < c.pairs.size(); ++k) {
      const ParticlePair& p = c.pairs[k];
      std::array<ConstraintRow, 3> rows_of_pair =
          contact_rows(c.a, c.b, p.normal, p.point - xa, p.point - xb);
      // A gap may close within the step; an overlap is taken back at up to recovery_speed.
      rows_of_pair[0].bias = std::min(p.overlap / h, recovery_speed);
      // The contact's identity and the pair's place in it: the same while both last.
      const std::uint64_t key = (c.id << 20) | std::min<std::uint64_t>(k, (1u << 20) - 1);
      if (const auto found = last_impulses_.find(key); found != last_impulses_.end()) {
        for (int r = 0; r < 3; ++r) rows_of_pair[r].impulse = found->second[std::size_t(r)];
      }
      rows.add_cone(rows_of_pair[0], rows_of_pair[1], rows_of_pair[2], mu, 0, key);
    }
  }
}

void ComplementarityContactSolver::remember_impulses(const RowGroup& rows) {
  last_impulses_.clear();
  for (const auto& [key, first] : rows.cones()) {
    last_impulses_[key] = {rows.rows()[first].impulse, rows.rows()[first + 1].impulse,
                           rows.rows()[first + 2].impulse};
  }
}

}  // namespace sluice
