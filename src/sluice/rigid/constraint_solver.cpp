#include "sluice/rigid/constraint_solver.hpp"

#include <algorithm>
#include <cmath>

namespace sluice {

namespace {

// The velocity of a row's bodies along the row, J (v, w).
double row_velocity(const std::vector<SystemBody>& bodies, const ConstraintRow& r) {
  double v = 0;
  if (r.a != ConstraintRow::kWorld) {
    const RigidBody& s = bodies[r.a].state;
    v += r.linear_a.dot(s.velocity) + r.angular_a.dot(s.angular_velocity());
  }
  if (r.b != ConstraintRow::kWorld) {
    const RigidBody& s = bodies[r.b].state;
    v += r.linear_b.dot(s.velocity) + r.angular_b.dot(s.angular_velocity());
  }
  return v;
}

// J M^-1 J^T of one body's part of a row (zero for a fixed body).
double inverse_mass_along(const SystemBody& body, const Vec3& linear, const Vec3& angular) {
  if (body.fixed) return 0;
  return linear.squaredNorm() / body.state.mass +
         angular.dot(body.state.inverse_world_inertia() * angular);
}

void apply(SystemBody& body, const Vec3& linear, const Vec3& angular, double impulse) {
  if (body.fixed) return;
  body.state.velocity += (impulse / body.state.mass) * linear;
  body.state.angular_momentum += impulse * angular;
  body.state.enforce_locks();
}

}  // namespace

ConstraintSolution solve_constraints(std::vector<SystemBody>& bodies,
                                     std::vector<ConstraintRow>& rows, int max_iterations,
                                     double tolerance) {
  std::vector<double> effective(rows.size(), 0);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const ConstraintRow& r = rows[k];
    double w = 0;
    if (r.a != ConstraintRow::kWorld) w += inverse_mass_along(bodies[r.a], r.linear_a, r.angular_a);
    if (r.b != ConstraintRow::kWorld) w += inverse_mass_along(bodies[r.b], r.linear_b, r.angular_b);
    effective[k] = w;
  }
  // Warm start: the impulses the rows come with act first.
  for (ConstraintRow& r : rows) {
    if (r.a != ConstraintRow::kWorld) apply(bodies[r.a], r.linear_a, r.angular_a, r.impulse);
    if (r.b != ConstraintRow::kWorld) apply(bodies[r.b], r.linear_b, r.angular_b, r.impulse);
  }
  ConstraintSolution out;
  for (out.iterations = 1; out.iterations <= max_iterations; ++out.iterations) {
    out.largest_change = 0;
    for (std::size_t k = 0; k < rows.size(); ++k) {
      ConstraintRow& r = rows[k];
      if (!(effective[k] > 0)) continue;  // a row on fixed bodies alone
      const double wanted = r.impulse + (r.bias - row_velocity(bodies, r)) / effective[k];
      const double next = std::clamp(wanted, r.lower, r.upper);
      const double change = next - r.impulse;
      r.impulse = next;
      if (r.a != ConstraintRow::kWorld) apply(bodies[r.a], r.linear_a, r.angular_a, change);
      if (r.b != ConstraintRow::kWorld) apply(bodies[r.b], r.linear_b, r.angular_b, change);
      out.largest_change = std::max(out.largest_change, std::abs(change));
    }
    if (out.largest_change <= tolerance) break;
  }
  out.iterations = std::min(out.iterations, max_iterations);
  return out;
}

}  // namespace sluice
