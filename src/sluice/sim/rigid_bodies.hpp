// The case's rigid bodies: built from their configuration (sampled shape, exact mass
// properties, contact material), advanced by the multibody contact system with the fluid's
// force held over the solid sub-steps, and seen by the fluid as moving walls made of body
// points (surface and interior particles fixed in the body).
#pragma once

#include <memory>
#include <vector>

#include "sluice/contact/multibody_system.hpp"
#include "sluice/io/case_config.hpp"

namespace sluice {

struct BodyPoint {
  std::size_t body = 0;
  Vec3 local = Vec3::Zero();  // in the principal frame, relative to the centre of mass
};

class RigidBodies {
 public:
  // Samples every body with `interior_layers` layers under its surface, adds the walls as
  // fixed contact bodies, and checks the starting layout. Throws InputError for a body outside
  // the domain, or overlapping another body or a wall.
  RigidBodies(const io::CaseConfig& config, int interior_layers);

  std::size_t count() const { return configs_.size(); }  // the case's bodies (not the walls)
  bool empty() const { return configs_.empty(); }
  const io::BodyConfig& config(std::size_t b) const { return configs_[b]; }
  const RigidBody& state(std::size_t b) const { return system_.bodies()[b].state; }
  const MultibodySystem& system() const { return system_; }
  // The orientation of body b's shape (its own axes as given), not of its principal axes.
  Eigen::Quaterniond shape_orientation(std::size_t b) const {
    return state(b).orientation * principal_[b].conjugate();
  }
  const std::vector<BodyPoint>& points() const { return points_; }

  // The fluid's force and moment (about the centre of mass) on each body, from the fluid's
  // last force evaluation; held over the solid sub-steps of the next advance.
  void set_fluid_loads(std::vector<Vec3> force, std::vector<Vec3> moment);
  // The solid step the contacts in reach need over a coming step of dt (dt when none is).
  double solid_step(double dt) { return system_.solid_step(dt); }
  // Advances by dt; returns the solid sub-steps taken.
  int advance(double dt);

  // World position, velocity and acceleration of body point k (the acceleration of the last
  // step, for the walls' pressure).
  Vec3 point_position(std::size_t k) const;
  Vec3 point_velocity(std::size_t k) const;
  Vec3 point_acceleration(std::size_t k) const;

  // Whether x lies inside a body or closer than `clearance` to one of its points.
  bool occupies(const Vec3& x, double clearance) const;

  const std::vector<Vec3>& fluid_force() const { return fluid_force_; }
  const std::vector<Vec3>& fluid_moment() const { return fluid_moment_; }
  long substeps() const { return system_.substeps_taken(); }
  int most_substeps() const { return most_substeps_; }

 private:
  bool body_occupies(std::size_t b, const Vec3& x, double clearance) const;
  // How deep the surface particles of body a lie inside body b (bodies or walls).
  double penetration(std::size_t a, std::size_t b) const;

  std::vector<io::BodyConfig> configs_;
  MultibodySystem system_;
  std::vector<BodyPoint> points_;
  std::vector<Vec3> local_min_, local_max_;    // each body's surface box, principal frame
  std::vector<Eigen::Quaterniond> principal_;  // per body: principal axes -> shape axes
  std::vector<Vec3> acceleration_, angular_acceleration_;
  std::vector<Vec3> fluid_force_, fluid_moment_;
  int most_substeps_ = 0;
};

}  // namespace sluice
