#include "sluice/sim/rigid_bodies.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "sluice/ccp/contact_rows.hpp"
#include "sluice/contact/contact_body_builder.hpp"
#include "sluice/core/errors.hpp"
#include "sluice/rigid/joined_mobility.hpp"
#include "sluice/sim/body_shapes.hpp"
#include "sluice/sim/prescribed_motion.hpp"

namespace sluice {

namespace {

// The surface particle of `body` nearest to `local` (in the body's frame) and its distance;
// the index is the particle count when the body has none.
std::pair<std::size_t, double> nearest_surface_particle(const ContactShape& body,
                                                        const Vec3& local) {
  double nearest = std::numeric_limits<double>::infinity();
  std::size_t closest = body.surface_position.size();
  for (std::size_t k = 0; k < body.surface_position.size(); ++k) {
    const double d2 = (local - body.surface_position[k]).squaredNorm();
    if (d2 < nearest) {
      nearest = d2;
      closest = k;
    }
  }
  return {closest, std::sqrt(nearest)};
}

// Principal axes of an inertia tensor as a proper rotation (columns), with the moments.
std::pair<Eigen::Matrix3d, Vec3> principal_axes(const Eigen::Matrix3d& inertia) {
  if (inertia.isDiagonal(1e-12 * inertia.norm()))
    return {Eigen::Matrix3d::Identity(), inertia.diagonal()};
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(inertia);
  Eigen::Matrix3d axes = solver.eigenvectors();
  if (axes.determinant() < 0) axes.col(2) *= -1;
  return {axes, solver.eigenvalues()};
}

// Sets a body's dynamic state from the pose and velocities of its shape's origin.
void place(RigidBody& state, const ShapePose& pose, const Vec3& com,
           const Eigen::Quaterniond& principal) {
  const Vec3 arm = pose.orientation * com;
  state.orientation = (pose.orientation * principal).normalized();
  state.position = pose.position + arm;
  state.velocity = pose.velocity + pose.angular_velocity.cross(arm);
  state.angular_momentum = state.world_inertia() * pose.angular_velocity;
  state.enforce_locks();
}

}  // namespace

RigidBodies::RigidBodies(const io::CaseConfig& config)
    : configs_(config.bodies),
      walls_(config.walls),
      spacing_(config.spacing),
      dimension_(config.dimension),
      system_(config.contact.distance, config.gravity, config.contact.substep_fraction,
              config.contact.method.value_or("penalty")) {
  const double dx = config.spacing;
  const int dimension = config.dimension;
  std::vector<std::string> names;
  for (std::size_t b = 0; b < configs_.size(); ++b) {
    const io::BodyConfig& c = configs_[b];
    const ShapeSample shape = sample_shape(c, dx, dimension);
    const auto [axes, moments] = principal_axes(shape.mass.inertia);
    MassProperties principal = shape.mass;
    principal.inertia = moments.asDiagonal();
    ContactBody body = make_contact_body(shape.surface, principal, c.material, shape.contact_radius,
                                         shape.flat_faces);
    // make_contact_body keeps the shape's axes; turn the particles into the principal frame.
    for (auto& x : body.surface_position) x = axes.transpose() * x;
    for (auto& n : body.surface_normal) n = axes.transpose() * n;
    body.spherical = shape.spherical;
    body.state.name = c.name;
    body.state.locked_translation = c.locked_translation;
    body.state.locked_rotation = c.locked_rotation;
    const Eigen::Quaterniond principal_rotation(axes);
    principal_.push_back(principal_rotation);
    axes_.push_back(axes);
    const Vec3 com = shape.mass.center_of_mass;
    centre_of_mass_.push_back(com);
    if (c.motion == io::BodyMotion::kPrescribed) {
      body.fixed = true;
      const PaddleAbsorber* absorber = nullptr;
      if (c.prescribed.kind == io::PrescribedKind::kWavemaker &&
          c.prescribed.wavemaker.active_absorption) {
        // Two spacings before the face: clear of the cells or particles the paddle's edge cuts.
        absorbers_.push_back(
            std::make_unique<PaddleAbsorber>(configs_[b], config.domain.min[2], 2 * dx));
        absorber = absorbers_.back().get();
      }
      body.prescribed = [c, com, principal_rotation, absorber](double time, RigidBody& state) {
        const PaddleCorrection correction = absorber ? absorber->at(time) : PaddleCorrection{};
        place(state, prescribed_pose(c, time, correction), com, principal_rotation);
      };
      body.prescribed(0.0, body.state);
    } else {
      ShapePose start{c.position, rotation_from_angles(c.rotation), c.velocity, c.angular_velocity};
      if (c.motion == io::BodyMotion::kFixed)
        start.velocity = start.angular_velocity = Vec3::Zero();
      body.fixed = c.motion == io::BodyMotion::kFixed;
      place(body.state, start, com, principal_rotation);
    }
    local_min_.push_back(Vec3::Constant(std::numeric_limits<double>::infinity()));
    local_max_.push_back(-local_min_.back());
    for (const Vec3& x : body.surface_position) {
      local_min_.back() = local_min_.back().cwiseMin(x);
      local_max_.back() = local_max_.back().cwiseMax(x);
    }
    system_.add(std::move(body));
    names.push_back(fmt::format("body '{}'", c.name));
  }
  // Walls as contact bodies, when there is a body to touch them.
  for (const auto& wall : config.walls) {
    if (configs_.empty()) break;
    if (wall.shape == io::WallShape::kTank) {
      for (auto& side : make_tank_walls(wall.box.min, wall.box.max, wall.open_sides, dx,
                                        wall.material, dimension)) {
        system_.add(std::move(side));
        names.push_back(fmt::format("wall '{}'", wall.name));
      }
    } else {
      if (wall.shape == io::WallShape::kBox) {
        system_.add(make_fixed_box(wall.box.min, wall.box.max, dx, wall.material, dimension));
      } else {
        // The plane over the domain and a contact distance beyond, so that a body at the
        // domain's edge still meets it.
        const Vec3 margin = Vec3::Constant(config.contact.distance);
        system_.add(make_plane_wall(wall.point, wall.normal, config.domain.min - margin,
                                    config.domain.max + margin, dx, wall.material, dimension));
      }
      names.push_back(fmt::format("wall '{}'", wall.name));
    }
  }
  const std::size_t n = configs_.size();
  system_.set_velocity_step(config.contact.velocity_step);
  add_joints(config);

  // The starting layout: inside the domain, and no two bodies overlapping.
  auto fail = [&](std::size_t b, const std::string& key, const std::string& problem) {
    const std::string& grain_key = configs_[b].key;
    throw InputError(configs_[b].position_file, configs_[b].position_line,
                     grain_key.empty() ? fmt::format("bodies[{}].{}", b, key) : grain_key, problem);
  };
  const double tolerance = 1e-9 * (config.domain.max - config.domain.min).norm();
  AxisBox inside = config.domain;
  inside.min.array() -= tolerance;
  inside.max.array() += tolerance;
  for (std::size_t b = 0; b < n; ++b) {
    const RigidBody& body = system_.bodies()[b].state;
    for (const Vec3& local : system_.shape(b).surface_position) {
      const Vec3 x = body.position + body.orientation * local;
      if (!inside.contains(x, dimension)) {
        fail(b, "position",
             fmt::format("body '{}' is not inside the domain: its surface reaches ({:.4g}, {:.4g}, "
                         "{:.4g})",
                         configs_[b].name, x[0], x[1], x[2]));
      }
    }
  }
  // Overlaps deeper than a tenth of the spacing, however deep (a body may sit wholly inside
  // another): every surface particle of a body is tested against every other body and wall.
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = 0; b < system_.bodies().size(); ++b) {
      if (b == a) continue;
      const double depth = penetration(a, b);
      if (depth > 0.1 * dx) {
        fail(a, "position",
             fmt::format("{} and {} overlap at the start: a surface particle of the first lies "
                         "{:.3g} m inside the second (more than a tenth of the spacing)",
                         names[a], names[b], depth));
      }
    }
  }
}

void RigidBodies::add_joints(const io::CaseConfig& config) {
  auto index_of = [&](const io::JointConfig& j, const std::string& name) {
    if (name == "world") return ConstraintRow::kWorld;
    std::vector<std::string> names{"world"};
    for (std::size_t b = 0; b < configs_.size(); ++b) {
      if (configs_[b].name == name) return b;
      names.push_back(configs_[b].name);
    }
    throw InputError(config.file(), j.line, j.key + ".bodies",
                     io::unknown_choice("body", name, names));
  };
  for (const io::JointConfig& j : config.joints) {
    Joint joint = make_joint(j.type, index_of(j, j.body_a), index_of(j, j.body_b), system_.bodies(),
                             j.anchor, j.axis);
    joint.name = j.name;
    joint.motor_speed = j.motor_speed;
    joint.motor_torque = j.motor_torque;
    system_.add_joint(joint);
  }
}

// How deep the surface particles of `a` lie inside `b`: for each, the distance behind the face
// of b's nearest surface particle (0 when none is behind it).
double RigidBodies::penetration(std::size_t body_a, std::size_t body_b) const {
  const ContactShape& a = system_.shape(body_a);
  const ContactShape& b = system_.shape(body_b);
  const RigidBody& state_a = system_.bodies()[body_a].state;
  const RigidBody& state_b = system_.bodies()[body_b].state;
  double deepest = 0;
  for (const Vec3& pa : a.surface_position) {
    const Vec3 x = state_b.orientation.conjugate() *
                   (state_a.position + state_a.orientation * pa - state_b.position);
    const auto [closest, distance] = nearest_surface_particle(b, x);
    if (closest < b.surface_position.size()) {
      deepest =
          std::max(deepest, -(x - b.surface_position[closest]).dot(b.surface_normal[closest]));
    }
  }
  return deepest;
}

void RigidBodies::command_velocity(std::size_t b, double time, const Vec3& velocity,
                                   const Vec3& angular_velocity) {
  if (b >= count() || configs_[b].motion != io::BodyMotion::kPrescribed) {
    throw std::invalid_argument("only a body whose motion is prescribed can be driven");
  }
  SystemBody& body = system_.bodies()[b];
  const RigidBody start = body.state;
  // Only along the motions the body is free in (a 2D body: in its plane, turning about y).
  Vec3 free_velocity = velocity, free_angular_velocity = angular_velocity;
  for (int k = 0; k < 3; ++k) {
    if (start.locked_translation[k]) free_velocity[k] = 0;
    if (start.locked_rotation[k]) free_angular_velocity[k] = 0;
  }
  body.prescribed = [start, time, velocity = free_velocity,
                     angular_velocity = free_angular_velocity](double t, RigidBody& state) {
    const double elapsed = t - time;
    const double angle = angular_velocity.norm() * elapsed;
    const Eigen::Quaterniond turn =
        angle > 0 ? Eigen::Quaterniond(Eigen::AngleAxisd(angle, angular_velocity.normalized()))
                  : Eigen::Quaterniond::Identity();
    state.position = start.position + elapsed * velocity;
    state.orientation = (turn * start.orientation).normalized();
    state.velocity = velocity;
    state.angular_momentum = state.world_inertia() * angular_velocity;
    state.enforce_locks();
  };
  body.prescribed(time, body.state);
}

std::vector<BodyKinematics> RigidBodies::motion() const {
  std::vector<BodyKinematics> out(count());
  for (std::size_t b = 0; b < count(); ++b) {
    const RigidBody& s = state(b);
    out[b].position = s.position;
    out[b].orientation = s.orientation;
    out[b].velocity = s.velocity;
    out[b].angular_velocity = s.angular_velocity();
  }
  return out;
}

BodyMobility RigidBodies::own_mobility(std::size_t b) const {
  BodyMobility m;
  if (configs_[b].motion != io::BodyMotion::kFree) return m;
  const RigidBody& s = state(b);
  Eigen::Matrix3d free_rotation = Eigen::Matrix3d::Zero();
  for (int a = 0; a < 3; ++a) {
    m.inverse_mass(a, a) = s.locked_translation[a] ? 0 : 1 / s.mass;
    free_rotation(a, a) = s.locked_rotation[a] ? 0 : 1;
  }
  m.inverse_inertia = free_rotation * s.inverse_world_inertia() * free_rotation;
  return m;
}

BodyMobility RigidBodies::mobility(std::size_t b) const {
  // A body in contact answers through the contact as much as through its own mass: a fluid
  // that solved for its velocity without the contact would move it into what holds it, and
  // the contact's answer, a step late, would pump energy into the water (two boxes landing on
  // each other: 50 J). Held by a contact, a body is immobile to the fluid for that step.
  if (system_.contact_force()[b].norm() > 0) return {};
  return own_mobility(b);
}

Eigen::MatrixXd RigidBodies::joined_mobility() const {
  return joined_mobility(Eigen::VectorXd());
}

Eigen::MatrixXd RigidBodies::joined_mobility(const Eigen::VectorXd& impulse) const {
  std::vector<Mat6> own(count(), Mat6::Zero());
  for (std::size_t b = 0; b < count(); ++b) {
    const BodyMobility m = own_mobility(b);
    own[b].topLeftCorner<3, 3>() = m.inverse_mass;
    own[b].bottomRightCorner<3, 3>() = m.inverse_inertia;
  }
  // The rows' Jacobian does not depend on the step (h = 1) nor on the drift taken back (0).
  RowGroup rows;
  for (const Joint& joint : system_.rigid().joints()) {
    add_joint_rows(joint, system_.bodies(), 1.0, 0.0, rows);
  }
  const std::size_t joint_rows = rows.size();
  // Each touching pair of surface particles keeps its normal velocity for the step, as a joint
  // would: the pressure moves no body into what holds it (a wheel into the bed), and lets it
  // roll, slide or turn along it; the contact's own force and friction act in the bodies'
  // advance. A body held by a contact, immobile instead, took no load at all.
  const std::vector<SystemBody>& bodies = system_.bodies();
  for (const Contact& c : system_.contact().contacts().contacts()) {
    const Vec3& xa = bodies[c.a].state.position;
    const Vec3& xb = bodies[c.b].state.position;
    for (const ParticlePair& p : c.pairs) {
      rows.add_row(contact_rows(c.a, c.b, p.normal, p.point - xa, p.point - xb)[0]);
    }
  }
  if (impulse.size() == 0 || rows.size() == joint_rows) return sluice::joined_mobility(own, rows);
  // The rows' impulses that would hold the bodies' row velocities against `impulse`; a contact
  // row whose impulse pulls its bodies together lets go (water squeezed under a wheel lifts it).
  const std::vector<Real> held = row_impulses(own, rows, impulse);
  RowGroup kept;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (r < joint_rows || held[r] >= 0) kept.add_row(rows.rows()[r]);
  }
  return sluice::joined_mobility(own, kept);
}

std::vector<BodyPoint> RigidBodies::points_under_surface(int layers) const {
  std::vector<BodyPoint> out;
  for (std::size_t b = 0; b < count(); ++b) {
    if (configs_[b].seen_as_one_particle) {
      out.push_back({b, Vec3::Zero()});
      continue;
    }
    for (const Vec3& x : sample_under_surface(configs_[b], spacing_, layers, dimension_))
      out.push_back({b, axes_[b].transpose() * (x - centre_of_mass_[b])});
  }
  return out;
}

std::vector<BodyPoint> RigidBodies::surface_points() const {
  std::vector<BodyPoint> out;
  for (std::size_t b = 0; b < count(); ++b) {
    for (const Vec3& x : system_.shape(b).surface_position) out.push_back({b, x});
  }
  return out;
}

// One array of every body's contact shape, bodies in order (the walls' shapes follow them in
// the system and are left out).
template <class T>
std::vector<T> RigidBodies::gather(std::vector<T> ContactShape::*member) const {
  std::vector<T> out;
  for (std::size_t b = 0; b < count(); ++b) {
    const std::vector<T>& values = system_.shape(b).*member;
    out.insert(out.end(), values.begin(), values.end());
  }
  return out;
}

std::vector<Vec3> RigidBodies::surface_normals() const {
  return gather(&ContactShape::surface_normal);
}

std::vector<double> RigidBodies::surface_areas() const {
  return gather(&ContactShape::surface_area);
}

bool RigidBodies::occupies(const Vec3& x, double clearance) const {
  for (std::size_t b = 0; b < count(); ++b) {
    if (body_occupies(b, x, clearance)) return true;
  }
  return false;
}

bool RigidBodies::body_occupies(std::size_t b, const Vec3& x, double clearance) const {
  const ContactShape& body = system_.shape(b);
  const RigidBody& state = system_.bodies()[b].state;
  const Vec3 local = state.orientation.conjugate() * (x - state.position);
  if ((local.array() < local_min_[b].array() - clearance).any() ||
      (local.array() > local_max_[b].array() + clearance).any()) {
    return false;
  }
  // Within the clearance of the face of the nearest surface particle (a point on a face midway
  // between its particles is on the body, not dx/sqrt(2) from it; a point within the clearance
  // of the particle itself is within it of the face too).
  const std::size_t closest = nearest_surface_particle(body, local).first;
  return (local - body.surface_position[closest]).dot(body.surface_normal[closest]) < clearance;
}

}  // namespace sluice
