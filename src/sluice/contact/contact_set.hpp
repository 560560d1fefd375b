// The contacts of one detection pass, with identities that persist from pass to pass. The
// narrow phase reports particle pairs; the pairs of one body pair whose normals lie within 45
// degrees of a contact's first pair form that contact (a box on a floor: one contact; a box
// in a corner: one per face). A contact takes over the tangential history of the contact of
// the last pass between the same bodies whose normal is closest to its own, within 60
// degrees: a contact that turns slowly, however far, keeps its Mindlin spring.
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "sluice/core/state_archive.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

// One particle pair of the narrow phase.
struct ParticlePair {
  Vec3 point = Vec3::Zero();   // where its force acts
  Vec3 normal = Vec3::Zero();  // unit, from body a into body b
  double overlap = 0;          // minus the gap between the faces
  double area = 0;             // the smaller of the two particles' areas
};

struct Contact {
  std::size_t a = 0, b = 0;                          // the normal points from a into b
  std::uint64_t id = 0;                              // the same while the contact lasts
  double overlap = 0;                                // the deepest pair's
  double area = 0;                                   // the pairs' areas, summed
  double weight = 0;                                 // the pairs' overlap^(3/2) times area, summed
  Vec3 point = Vec3::Zero(), normal = Vec3::Zero();  // weighted by overlap^(3/2) times area
  std::vector<ParticlePair> pairs;
  Vec3 tangential = Vec3::Zero();  // accumulated tangential displacement (Mindlin)
};

inline void archive_state(StateArchive& a, ParticlePair& p) {
  a(p.point, p.normal, p.overlap, p.area);
}
inline void archive_state(StateArchive& a, Contact& c) {
  a(c.a, c.b, c.id, c.overlap, c.area, c.weight, c.point, c.normal, c.pairs, c.tangential);
}

class ContactSet {
 public:
  // Starts a pass: the contacts found so far become the last pass's.
  void begin_pass();
  // Adds a pair of bodies a < b; the pairs of one body pair arrive together.
  void add(std::size_t a, std::size_t b, const ParticlePair& pair);
  // Closes the pass: weighted points and normals, identities and histories.
  void end_pass();

  std::vector<Contact>& contacts() { return contacts_; }
  const std::vector<Contact>& contacts() const { return contacts_; }

  // Checkpoints: the contacts in their order (the next pass takes over their identities and
  // springs) and the next identity.
  void archive_state(StateArchive& a) { a(contacts_, next_id_); }

 private:
  static std::uint64_t key(std::size_t a, std::size_t b) { return (std::uint64_t(a) << 32) | b; }

  std::vector<Contact> contacts_, last_;
  std::unordered_map<std::uint64_t, std::pair<std::size_t, std::size_t>> last_range_;
  std::vector<Vec3> first_normal_;   // per contact: its first pair's normal (groups the pairs)
  std::size_t body_pair_begin_ = 0;  // the first contact of the body pair being added
  std::uint64_t next_id_ = 0;
};

}  // namespace sluice
