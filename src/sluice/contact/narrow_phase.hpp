// The narrow phase of contact (seed 000: Amaro Junior, Cheng & Osello 2019): for two bodies in
// reach, each surface particle k of one meets the nearest particle l of the other whose face
// faces its own, closer than the contact distance. The pair gives a contact normal from the
// faces, n_c = (n_k - n_l) / |n_k - n_l|, and the gap between the faces along it,
// (r_l - r_k) . n_c, rather than the bumpy particle-to-particle direction.
#pragma once

#include <cstdint>
#include <vector>

#include "sluice/contact/contact_body.hpp"
#include "sluice/contact/contact_set.hpp"
#include "sluice/contact/world_surface.hpp"

namespace sluice {

class NarrowPhase {
 public:
  explicit NarrowPhase(double contact_distance) : distance_(contact_distance) {}

  // Adds the particle pairs of bodies a < b that overlap by more than `least_overlap` to
  // `contacts`: 0 for the penalty law; minus an envelope for the complementarity step, which
  // must see a gap before it closes.
  void find(std::size_t a, std::size_t b, const std::vector<SystemBody>& bodies,
            const std::vector<ContactShape>& shapes, const std::vector<WorldSurface>& surfaces,
            ContactSet& contacts, double least_overlap = 0);

 private:
  double distance_;
  PointGrid pair_grid_;  // scratch: one moving body's particles near another
  std::vector<std::uint32_t> near_a_, near_b_;
};

}  // namespace sluice
