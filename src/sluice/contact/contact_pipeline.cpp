#include "sluice/contact/contact_pipeline.hpp"

#include <algorithm>

namespace sluice {

namespace {

// How far the box lies in front of the plane: the smallest signed distance of its corners.
double height_above(const AxisBox& box, const HalfSpace& plane) {
  const Vec3 centre = 0.5 * (box.min + box.max), half = 0.5 * (box.max - box.min);
  return (centre - plane.point).dot(plane.normal) - half.dot(plane.normal.cwiseAbs());
}

// Whether bodies a and b come within `margin` of each other: their boxes, and a plane wall's
// plane rather than its box (which spans the domain).
bool within(const std::vector<ContactShape>& shapes, std::size_t a, std::size_t b,
            const AxisBox& box_a, const AxisBox& box_b, double margin) {
  if (!box_a.overlaps(box_b, margin)) return false;
  if (shapes[a].half_space) return height_above(box_b, *shapes[a].half_space) <= margin;
  if (shapes[b].half_space) return height_above(box_a, *shapes[b].half_space) <= margin;
  return true;
}

}  // namespace

ContactPipeline::ContactPipeline(double contact_distance, std::unique_ptr<ContactSolver> solver)
    : distance_(contact_distance), solver_(std::move(solver)), narrow_phase_(contact_distance) {}

void ContactPipeline::place(const std::vector<SystemBody>& bodies) {
  surfaces_.resize(shapes_.size());
  for (std::size_t b = 0; b < shapes_.size(); ++b)
    surfaces_[b].update(shapes_[b], bodies[b], 2 * distance_);
}

void ContactPipeline::candidates(const std::vector<SystemBody>& bodies,
                                 const std::vector<double>& growth, double margin) {
  const std::size_t n = shapes_.size();
  boxes_.resize(n);
  fixed_.resize(n);
  large_.resize(n);
  for (std::size_t b = 0; b < n; ++b) {
    boxes_[b] = surfaces_[b].bounds();
    if (!growth.empty()) {
      boxes_[b].min.array() -= growth[b];
      boxes_[b].max.array() += growth[b];
    }
    fixed_[b] = bodies[b].fixed;
    large_[b] = shapes_[b].half_space.has_value();
  }
  broad_phase_.find(boxes_, fixed_, large_, margin, pairs_);
  std::erase_if(pairs_, [&](const BodyPair& p) {
    return !within(shapes_, p.first, p.second, boxes_[p.first], boxes_[p.second], margin);
  });
}

void ContactPipeline::evaluate(const std::vector<SystemBody>& bodies, double dt,
                               std::vector<Vec3>& force, std::vector<Vec3>& torque) {
  place(bodies);
  candidates(bodies, {}, distance_);
  contacts_.begin_pass();
  for (const auto& [a, b] : pairs_) narrow_phase_.find(a, b, bodies, shapes_, surfaces_, contacts_);
  contacts_.end_pass();
  solver_->solve(contacts_, bodies, shapes_, dt, force, torque);
}

void ContactPipeline::contact_constraints(const std::vector<SystemBody>& bodies, double h,
                                          double recovery_speed, RowGroup& rows) {
  place(bodies);
  candidates(bodies, {}, distance_);
  contacts_.begin_pass();
  // Pairs whose gap may close within the step: up to the contact distance apart.
  for (const auto& [a, b] : pairs_) {
    narrow_phase_.find(a, b, bodies, shapes_, surfaces_, contacts_, -distance_);
  }
  contacts_.end_pass();
  solver_->add_cones(contacts_, bodies, shapes_, h, recovery_speed, rows);
}

double ContactPipeline::stable_step(const std::vector<SystemBody>& bodies, double dt) {
  place(bodies);
  // How far each body's surface can travel in dt: its speed and its spin times its size.
  const std::size_t n = shapes_.size();
  std::vector<double> speed(n), growth(n);
  for (std::size_t b = 0; b < n; ++b) {
    const RigidBody& s = bodies[b].state;
    const AxisBox& box = surfaces_[b].bounds();
    speed[b] = s.angular_velocity().norm() * (box.max - box.min).norm();
    growth[b] = (s.velocity.norm() + speed[b]) * dt;
  }
  candidates(bodies, growth, distance_);
  double step = dt;
  for (const auto& [a, b] : pairs_) {
    const double approach =
        (bodies[b].state.velocity - bodies[a].state.velocity).norm() + speed[a] + speed[b];
    // In reach within this step: closer than the way the two can travel towards each other.
    const double reach = approach * dt + distance_;
    if (!within(shapes_, a, b, surfaces_[a].bounds(), surfaces_[b].bounds(), reach)) continue;
    step = std::min(step, solver_->pair_step(a, b, approach, bodies, shapes_));
  }
  return step;
}

}  // namespace sluice
