#include "sluice/rigid/rigid_integrator.hpp"

#include <cmath>

namespace sluice {

void RigidBody::enforce_locks() {
  for (int a = 0; a < 3; ++a) {
    if (locked_translation[a]) velocity[a] = 0;
  }
  if (locked_rotation[0] || locked_rotation[1] || locked_rotation[2]) {
    Vec3 omega = angular_velocity();
    for (int a = 0; a < 3; ++a) {
      if (locked_rotation[a]) omega[a] = 0;
    }
    angular_momentum = world_inertia() * omega;
  }
}

void kick(RigidBody& body, const Vec3& force, const Vec3& torque, double dt) {
  body.velocity += (dt / body.mass) * force;
  body.angular_momentum += dt * torque;
  body.enforce_locks();
}

namespace {
// Exact free rotation about principal axis k for a time h: the body turns by the angle
// pi_k h / I_k about that axis, and the body-frame angular momentum turns the other way.
void rotate_about_principal_axis(RigidBody& body, Vec3& pi, int k, double h) {
  const double angle = pi[k] * h / body.principal_inertia[k];
  const Eigen::AngleAxisd turn(angle, Vec3::Unit(k));
  pi = turn.inverse() * pi;
  body.orientation = (body.orientation * Eigen::Quaterniond(turn)).normalized();
}
}  // namespace

void drift(RigidBody& body, double dt) {
  body.position += dt * body.velocity;
  Vec3 pi = body.orientation.conjugate() * body.angular_momentum;  // body frame
  if (pi.squaredNorm() == 0) return;
  rotate_about_principal_axis(body, pi, 0, 0.5 * dt);
  rotate_about_principal_axis(body, pi, 1, 0.5 * dt);
  rotate_about_principal_axis(body, pi, 2, dt);
  rotate_about_principal_axis(body, pi, 1, 0.5 * dt);
  rotate_about_principal_axis(body, pi, 0, 0.5 * dt);
  // The world angular momentum is unchanged by construction; recompute it from pi only to
  // keep it consistent with the normalised quaternion.
  body.angular_momentum = body.orientation * pi;
}

}  // namespace sluice
