// What a fluid may ask of the bodies' and walls' shapes: points fixed in each body, layer by
// layer under its surface, and its surface particles (with normals and areas, as contact uses
// them); whether a place is taken by a body; the signed distance, closest point and normal to
// each body and to the walls. The case's bodies implement it (sim/rigid_bodies.hpp).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "sluice/coupling/body_motion.hpp"
#include "sluice/geometry/signed_distance.hpp"

namespace sluice {

// How a body answers a force and a moment: its inverse mass along each free world axis and
// its inverse inertia (world), zero along locked motions, for a body held by a contact, and
// for a body that does not answer forces (fixed, prescribed). A fluid that solves for the
// bodies' velocities with its own pressure needs it.
struct BodyMobility {
  Eigen::Matrix3d inverse_mass = Eigen::Matrix3d::Zero();  // (world)
  Eigen::Matrix3d inverse_inertia = Eigen::Matrix3d::Zero();
};

class BodyGeometry {
 public:
  virtual ~BodyGeometry() = default;
  virtual std::size_t body_count() const = 0;
  // The bodies' kinematics now (no acceleration yet).
  virtual std::vector<BodyKinematics> motion() const = 0;
  // Points at depths dx/2, 3 dx/2, ... under each body's surface, `layers` of them: a fluid
  // whose boundary lies half a spacing outside its boundary particles then meets the true
  // surface.
  virtual std::vector<BodyPoint> points_under_surface(int layers) const = 0;
  // The surface particles that contact uses, on each body's faces.
  virtual std::vector<BodyPoint> surface_points() const = 0;
  // Their outward normals (in the body's principal frame) and the areas they stand for, in
  // the order of surface_points().
  virtual std::vector<Vec3> surface_normals() const = 0;
  virtual std::vector<double> surface_areas() const = 0;
  // Whether x lies inside a body or closer than `clearance` to its surface (to the face of the
  // nearest surface particle).
  virtual bool occupies(const Vec3& x, double clearance) const = 0;

  // The nearest point of body b's surface to x (world), at the body's present pose: signed
  // distance (< 0 inside), closest point and outward normal, in the world.
  virtual SurfacePoint nearest_on_body(std::size_t b, const Vec3& x) const = 0;
  // The nearest point of the walls to x: distance < 0 inside a wall's solid, the normal
  // pointing out of the solid (infinite distance when there is no wall).
  virtual SurfacePoint nearest_on_walls(const Vec3& x) const = 0;
  // Body b's mobility now (immobile unless the bodies say otherwise).
  virtual BodyMobility mobility(std::size_t /*b*/) const { return {}; }
  // The bodies' mobility together, 6 rows and columns per body (linear, then angular; world),
  // with the joints between them kept (rigid/joined_mobility.hpp); without joints, each
  // body's mobility() on the diagonal.
  virtual Eigen::MatrixXd joined_mobility() const {
    const auto n = static_cast<Eigen::Index>(body_count());
    Eigen::MatrixXd w = Eigen::MatrixXd::Zero(6 * n, 6 * n);
    for (Eigen::Index b = 0; b < n; ++b) {
      const BodyMobility m = mobility(static_cast<std::size_t>(b));
      w.block<3, 3>(6 * b, 6 * b) = m.inverse_mass;
      w.block<3, 3>(6 * b + 3, 6 * b + 3) = m.inverse_inertia;
    }
    return w;
  }
  // joined_mobility() without the contacts that `impulse` (6 per body, as W's rows) would pull
  // apart: a contact holds a body back from what it stands on, never onto it.
  virtual Eigen::MatrixXd joined_mobility(const Eigen::VectorXd& /*impulse*/) const {
    return joined_mobility();
  }
};

}  // namespace sluice
