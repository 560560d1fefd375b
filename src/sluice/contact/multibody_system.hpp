// Rigid bodies in contact (seed 000: Amaro Junior, Cheng & Osello 2019). Each body carries
// surface particles with the outward normal and area of the face they sample. For two bodies
// within reach, each surface particle k of one meets the nearest particle l of the other whose
// face faces its own, closer than the contact distance: the pair gives a contact normal from
// the faces, n_c = (n_k - n_l) / |n_k - n_l|, and the gap between the faces along it,
// (r_l - r_k) . n_c, rather than the bumpy particle-to-particle direction. The overlapping
// pairs of one body pair and one contact direction form one contact. Each pair carries the
// Hertz law of the bodies at its own overlap, with the dashpot of its own normal velocity,
// times its share of the pairs' area: a face pressed evenly follows the Hertz-Mindlin law of
// the bodies whatever the number of pairs, a tilt shifts the force to the deeper side, and
// rocking is damped.
// Solid sub-cycling: a step of the caller (the fluid's) is split into as many solid sub-steps
// as the stiffest contact in reach needs; with no contact in reach it is one step.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sluice/contact/hertz_mindlin.hpp"
#include "sluice/contact/world_surface.hpp"
#include "sluice/rigid/rigid_body.hpp"

namespace sluice {

// The solid side of a plane wall: the points x with (x - point) . normal < 0.
struct HalfSpace {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();  // unit, out of the solid
};

struct ContactBody {
  RigidBody state;
  ContactMaterial material;
  double contact_radius = 0;  // R in Hertz's law; 0 = flat (a wall)
  bool fixed = false;  // walls, fixed and prescribed bodies: infinite mass, not moved by forces
  // A prescribed body: sets its state (pose and velocities) at a time; called every sub-step.
  std::function<void(double time, RigidBody& state)> prescribed;
  bool flat_faces = true;  // every surface particle lies on a plane face (boxes, meshes, walls)
  // A sphere (2D: a disc) of radius contact_radius about the centre of mass: its overlap is
  // then computed exactly from its centre, smooth as it rolls or glances off.
  bool spherical = false;
  // A plane wall: reach is measured to its plane, since the bounding box of a sloping plane
  // spans the domain and would put every body in reach.
  std::optional<HalfSpace> half_space;
  // Surface particles in the principal frame, relative to the centre of mass.
  std::vector<Vec3> surface_position;
  std::vector<Vec3> surface_normal;
  std::vector<double> surface_area;
};

struct MultibodyEnergy {
  double kinetic = 0;
  double potential = 0;  // in the gravity field, relative to z = 0 along -g
  double elastic = 0;    // stored in the contact springs
  double total() const { return kinetic + potential + elastic; }
};

class MultibodySystem {
 public:
  // contact_distance: particle pairs closer than this are examined (about the spacing).
  // substep_fraction: solid step = this fraction of the shortest contact period (1/20-1/50).
  MultibodySystem(double contact_distance, Vec3 gravity, double substep_fraction = 1.0 / 30);

  std::size_t add(ContactBody body);

  // Advances by dt. `force` and `torque` (one per body, may be empty) are held over the
  // sub-steps, as the fluid's force is. Returns the number of sub-steps taken.
  int advance(double dt, const std::vector<Vec3>& force = {}, const std::vector<Vec3>& torque = {});

  const std::vector<ContactBody>& bodies() const { return bodies_; }
  std::vector<ContactBody>& bodies() { return bodies_; }
  MultibodyEnergy energy() const;
  // Contact force and torque (about the centre of mass) on each body from the last sub-step.
  const std::vector<Vec3>& contact_force() const { return contact_force_; }
  const std::vector<Vec3>& contact_torque() const { return contact_torque_; }
  // The deepest overlap at any sub-step so far.
  double deepest_overlap_ever() const { return deepest_overlap_ever_; }
  long substeps_taken() const { return substeps_; }

  // The solid step that the contacts in reach during a coming step of dt need: a
  // `substep_fraction` of the shortest contact period among them; dt when none is in reach.
  double solid_step(double dt);

 private:
  struct ParticlePair {
    Vec3 point;      // where its force acts
    double overlap;  // minus the gap between the faces
    double area;     // the smaller of the two particles' areas
  };
  struct Contact {
    std::size_t a = 0, b = 0;  // the normal points from a into b
    double overlap = 0;        // the deepest pair's
    double area = 0;           // the pairs' areas, summed
    double weight = 0;         // the pairs' overlap^(3/2) times area, summed
    Vec3 point = Vec3::Zero(), normal = Vec3::Zero();
    std::vector<ParticlePair> pairs;
  };

  void place_surfaces();
  // Whether bodies a and b (placed) come within `margin` of each other: their bounding boxes,
  // and a plane wall's plane.
  bool in_reach(std::size_t a, std::size_t b, double margin) const;
  std::vector<Contact> find_contacts();
  void apply_contacts(double dt);
  const ContactPair& pair(std::size_t a, std::size_t b);

  double contact_distance_;
  Vec3 gravity_;
  double substep_fraction_;
  std::vector<ContactBody> bodies_;
  std::vector<WorldSurface> surfaces_;  // bodies_' surface particles in the world
  PointGrid pair_grid_;                 // scratch: one moving body's particles near another
  std::vector<Vec3> contact_force_, contact_torque_;
  std::map<std::uint64_t, Vec3> tangential_;  // accumulated tangential displacement per contact
  std::map<std::uint64_t, ContactPair> pairs_;
  double elastic_energy_ = 0;
  double deepest_overlap_ = 0;
  double deepest_overlap_ever_ = 0;
  long substeps_ = 0;
  double time_ = 0;
};

}  // namespace sluice
