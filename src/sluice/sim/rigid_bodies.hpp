// The case's rigid bodies: built from their configuration (sampled shape, exact mass
// properties, contact material) into the multibody contact system, with the walls as fixed
// contact bodies. A fluid sees their shapes through BodyGeometry: points fixed in each body
// under its surface, and the places they take.
#pragma once

#include <memory>
#include <vector>

#include "sluice/contact/multibody_system.hpp"
#include "sluice/coupling/body_geometry.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/sim/paddle_absorber.hpp"

namespace sluice {

class RigidBodies final : public BodyGeometry {
 public:
  // Builds every body, adds the walls as fixed contact bodies, and checks the starting layout.
  // Throws InputError for a body outside the domain, or overlapping another body or a wall.
  explicit RigidBodies(const io::CaseConfig& config);

  std::size_t count() const { return configs_.size(); }  // the case's bodies (not the walls)
  bool empty() const { return configs_.empty(); }
  const io::BodyConfig& config(std::size_t b) const { return configs_[b]; }
  const RigidBody& state(std::size_t b) const { return system_.bodies()[b].state; }
  const MultibodySystem& system() const { return system_; }
  MultibodySystem& system() { return system_; }
  // The orientation of body b's shape (its own axes as given), not of its principal axes.
  Eigen::Quaterniond shape_orientation(std::size_t b) const {
    return state(b).orientation * principal_[b].conjugate();
  }

  long substeps() const { return system_.substeps_taken(); }
  // From `time` on, prescribed body b moves on from where it stands at velocity `velocity` (of
  // its centre of mass) turning at `angular_velocity` [rad/s] (each along the motions the body
  // is not locked in; a 2D body's in its plane), in place of its case's motion: a
  // script's controller sets it before each step (python/). Throws std::invalid_argument for a
  // body whose motion is not prescribed. Not kept in checkpoints: a resumed run follows the
  // case's motion until it is commanded again.
  void command_velocity(std::size_t b, double time, const Vec3& velocity,
                        const Vec3& angular_velocity);
  // Checkpoints: the bodies' state and their contacts (shapes and joints come from the case),
  // and the paddles' absorption.
  void archive_state(StateArchive& a) {
    a.section("bodies");
    system_.archive_state(a);
    for (auto& absorber : absorbers_) a(*absorber);
  }
  // Paddles with active absorption read the water before them at `time`, the start of a step.
  void absorb_waves(double time, const FluidObservation& fluid) {
    for (auto& absorber : absorbers_) absorber->measure(time, fluid);
  }

  // BodyGeometry
  std::size_t body_count() const override { return count(); }
  std::vector<BodyKinematics> motion() const override;
  BodyMobility mobility(std::size_t b) const override;
  Eigen::MatrixXd joined_mobility() const override;
  Eigen::MatrixXd joined_mobility(const Eigen::VectorXd& impulse) const override;
  std::vector<BodyPoint> points_under_surface(int layers) const override;
  std::vector<BodyPoint> surface_points() const override;
  std::vector<Vec3> surface_normals() const override;
  std::vector<double> surface_areas() const override;
  bool occupies(const Vec3& x, double clearance) const override;
  SurfacePoint nearest_on_body(std::size_t b, const Vec3& x) const override;
  SurfacePoint nearest_on_walls(const Vec3& x) const override;

 private:
  // Body b's mobility by its mass, inertia and locked motions alone (its contacts aside).
  BodyMobility own_mobility(std::size_t b) const;
  bool body_occupies(std::size_t b, const Vec3& x, double clearance) const;
  // The case's joints, their bodies found by name (throws InputError for an unknown one).
  void add_joints(const io::CaseConfig& config);
  template <class T>
  std::vector<T> gather(std::vector<T> ContactShape::*member) const;
  // How deep the surface particles of body a lie inside body b (bodies or walls).
  double penetration(std::size_t a, std::size_t b) const;

  std::vector<io::BodyConfig> configs_;
  std::vector<io::WallConfig> walls_;
  double spacing_;
  int dimension_;
  MultibodySystem system_;
  std::vector<Vec3> local_min_, local_max_;    // each body's surface box, principal frame
  std::vector<Eigen::Quaterniond> principal_;  // per body: principal axes -> shape axes
  std::vector<Eigen::Matrix3d> axes_;          // the same as a matrix (its columns)
  std::vector<Vec3> centre_of_mass_;           // in the shape's frame
  // Paddles' active absorption; the bodies' motion closures keep pointers to them.
  std::vector<std::unique_ptr<PaddleAbsorber>> absorbers_;
};

}  // namespace sluice
