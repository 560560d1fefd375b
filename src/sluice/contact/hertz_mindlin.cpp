#include "sluice/contact/hertz_mindlin.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>

namespace sluice {

namespace {

double inverse_or_zero(double x) {
  return (x > 0 && std::isfinite(x)) ? 1 / x : 0;
}

// Speed at which the dimensionless Hertz oscillator with damping gamma leaves contact.
double rebound_speed(double gamma) {
  const double dt = 2e-4;  // the undamped contact lasts about 3.2 in these units
  double x = 0, v = 1;
  auto acceleration = [gamma](double x, double v) {
    const double s = std::max(x, 0.0);
    return -std::pow(s, 1.5) - gamma * std::pow(s, 0.25) * v;
  };
  for (int step = 0; step < 200000; ++step) {
    // Classical Runge-Kutta; contact ends when the force (spring plus dashpot) is no longer
    // repulsive, the moment the law clamps it to zero.
    const double k1x = v, k1v = acceleration(x, v);
    const double k2x = v + 0.5 * dt * k1v,
                 k2v = acceleration(x + 0.5 * dt * k1x, v + 0.5 * dt * k1v);
    const double k3x = v + 0.5 * dt * k2v,
                 k3v = acceleration(x + 0.5 * dt * k2x, v + 0.5 * dt * k2v);
    const double k4x = v + dt * k3v, k4v = acceleration(x + dt * k3x, v + dt * k3v);
    x += dt / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    v += dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (v < 0 && (x <= 0 || acceleration(x, v) >= 0)) return -v;
  }
  return 0;
}

}  // namespace

double hertz_damping_for_restitution(double restitution) {
  if (!(restitution > 0 && restitution <= 1)) {
    throw std::invalid_argument("restitution must lie in (0, 1]");
  }
  if (restitution == 1) return 0;
  double low = 0, high = 1;
  while (rebound_speed(high) > restitution) high *= 2;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double mid = 0.5 * (low + high);
    (rebound_speed(mid) > restitution ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

double HertzDampingTable::gamma(double restitution) {
  if (const auto found = known_.find(restitution); found != known_.end()) return found->second;
  const double value = hertz_damping_for_restitution(restitution);
  known_.emplace(restitution, value);
  return value;
}

ContactPair make_contact_pair(const ContactMaterial& a, double mass_a, double radius_a,
                              const ContactMaterial& b, double mass_b, double radius_b,
                              HertzDampingTable& damping) {
  ContactPair p;
  p.effective_mass = 1 / (inverse_or_zero(mass_a) + inverse_or_zero(mass_b));
  p.effective_radius = 1 / (inverse_or_zero(radius_a) + inverse_or_zero(radius_b));
  p.effective_young =
      1 / ((1 - a.poisson * a.poisson) / a.young + (1 - b.poisson * b.poisson) / b.young);
  const double shear_a = a.young / (2 * (1 + a.poisson)), shear_b = b.young / (2 * (1 + b.poisson));
  p.effective_shear = 1 / ((2 - a.poisson) / shear_a + (2 - b.poisson) / shear_b);
  p.restitution = std::min(a.restitution, b.restitution);
  p.friction = std::min(a.friction, b.friction);
  p.normal_stiffness = 4.0 / 3.0 * p.effective_young * std::sqrt(p.effective_radius);
  p.normal_damping =
      damping.gamma(p.restitution) * std::sqrt(p.effective_mass * p.normal_stiffness);
  const double log_e = std::log(p.restitution);
  const double beta = log_e / std::sqrt(log_e * log_e + std::numbers::pi * std::numbers::pi);
  p.tangential_damping_ratio = 2 * std::sqrt(5.0 / 6.0) * std::abs(beta);
  return p;
}

double hertz_normal_force(const ContactPair& pair, double overlap, double normal_velocity) {
  const double spring = pair.normal_stiffness * overlap * std::sqrt(overlap);
  const double damper = -pair.normal_damping * std::sqrt(std::sqrt(overlap)) * normal_velocity;
  return std::max(0.0, spring + damper);  // a penalty contact only pushes
}

Vec3 mindlin_tangential_force(const ContactPair& pair, double overlap, const Vec3& normal,
                              const Vec3& tangential_velocity, double normal_force,
                              Vec3& tangential, double dt, double& elastic_energy, bool& sliding) {
  // Tangential displacement: keep its length, turn it into the current tangent plane.
  const double length = tangential.norm();
  tangential -= tangential.dot(normal) * normal;
  const double projected = tangential.norm();
  if (projected > 0) tangential *= length / projected;
  tangential += dt * tangential_velocity;

  const double stiffness = 8 * pair.effective_shear * std::sqrt(pair.effective_radius * overlap);
  Vec3 force = -stiffness * tangential - pair.tangential_damping_ratio *
                                             std::sqrt(stiffness * pair.effective_mass) *
                                             tangential_velocity;
  const double limit = pair.friction * normal_force;
  sliding = false;
  if (force.norm() > limit) {
    sliding = true;
    const double norm = force.norm();
    force = norm > 0 ? Vec3(force * (limit / norm)) : Vec3::Zero();
    // The spring alone carries the Coulomb force from here on.
    tangential = stiffness > 0 ? Vec3(-force / stiffness) : Vec3::Zero();
  }
  elastic_energy += 0.5 * stiffness * tangential.squaredNorm();
  return force;
}

ContactForce hertz_mindlin_force(const ContactPair& pair, double overlap, const Vec3& normal,
                                 const Vec3& relative_velocity, Vec3& tangential, double dt) {
  ContactForce out;
  const double v_n = relative_velocity.dot(normal);
  out.normal = hertz_normal_force(pair, overlap, v_n);
  out.elastic_energy = 0.4 * pair.normal_stiffness * overlap * overlap * std::sqrt(overlap);
  const Vec3 f_t =
      mindlin_tangential_force(pair, overlap, normal, relative_velocity - v_n * normal, out.normal,
                               tangential, dt, out.elastic_energy, out.sliding);
  out.force = out.normal * normal + f_t;
  return out;
}

}  // namespace sluice
