#include "sluice/contact/contact_pipeline.hpp"

#include <algorithm>
#include <iterator>

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

void ContactPipeline::place(const std::vector<SystemBody>& bodies, bool here_only) {
  surfaces_.resize(shapes_.size());
  for (std::size_t b = 0; b < shapes_.size(); ++b) {
    // Another process's bodies stay where the step's start put them (pairs_in_reach): their
    // pairs are its own.
    if (here_only && !here_.empty() && !here_[b] && !bodies[b].fixed) continue;
    surfaces_[b].update(shapes_[b], bodies[b], 2 * distance_);
  }
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
  place(bodies, true);
  candidates(bodies, {}, distance_);
  if (!here_.empty()) {  // another process's pairs are its own
    std::erase_if(pairs_, [&](const BodyPair& p) { return !here_[p.first] && !here_[p.second]; });
  }
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

template <class InReach>
void ContactPipeline::each_pair_in_reach(const std::vector<SystemBody>& bodies, double dt,
                                         double reach, InReach&& in_reach) {
  place(bodies);
  // How far each body's surface can travel in dt: its speed and its spin times its size.
  const std::size_t n = shapes_.size();
  std::vector<double> speed(n), growth(n);
  for (std::size_t b = 0; b < n; ++b) {
    const RigidBody& s = bodies[b].state;
    const AxisBox& box = surfaces_[b].bounds();
    speed[b] = s.angular_velocity().norm() * (box.max - box.min).norm();
    growth[b] = reach * (s.velocity.norm() + speed[b]) * dt;
  }
  candidates(bodies, growth, distance_);
  for (const auto& [a, b] : pairs_) {
    const double approach =
        (bodies[b].state.velocity - bodies[a].state.velocity).norm() + speed[a] + speed[b];
    // In reach within this step: closer than the way the two can travel towards each other.
    const double margin = reach * approach * dt + distance_;
    if (!within(shapes_, a, b, surfaces_[a].bounds(), surfaces_[b].bounds(), margin)) continue;
    in_reach(a, b, approach);
  }
}

double ContactPipeline::stable_step(const std::vector<SystemBody>& bodies, double dt) {
  // A split run wants the pairs in twice the step's reach as well (pairs_in_reach), found in
  // the same pass; the step comes from those within the step's reach alone, as on one process.
  const bool islands = !here_.empty();
  island_pairs_.clear();
  double step = dt;
  each_pair_in_reach(
      bodies, dt, islands ? 2.0 : 1.0, [&](std::size_t a, std::size_t b, double approach) {
        if (islands) island_pairs_.emplace_back(a, b);
        const double margin = approach * dt + distance_;
        if (islands && !within(shapes_, a, b, surfaces_[a].bounds(), surfaces_[b].bounds(), margin))
          return;
        step = std::min(step, solver_->pair_step(a, b, approach, bodies, shapes_));
      });
  island_pairs_dt_ = islands ? dt : -1;
  return step;
}

std::vector<IslandPair> ContactPipeline::pairs_in_reach(const std::vector<SystemBody>& bodies,
                                                        double dt) {
  // Twice the step's reach: the bodies' speeds change over the step (gravity, the fluid). The
  // step's stable_step has found them already, but for the first step of a run.
  if (island_pairs_dt_ == dt) return island_pairs_;
  std::vector<IslandPair> out;
  each_pair_in_reach(bodies, dt, 2.0,
                     [&](std::size_t a, std::size_t b, double) { out.emplace_back(a, b); });
  return out;
}

void ContactPipeline::write_share(StateArchive& a) {
  std::vector<Contact> mine = contacts_.contacts();
  ContactSolver::Figures f = solver_->figures();
  a(mine, f.stored_energy, f.deepest_overlap, f.deepest_overlap_ever);
}

void ContactPipeline::read_shares(std::vector<StateArchive>& parts) {
  std::vector<Contact> all;
  ContactSolver::Figures total;
  for (StateArchive& part : parts) {
    std::vector<Contact> theirs;
    ContactSolver::Figures f;
    part(theirs, f.stored_energy, f.deepest_overlap, f.deepest_overlap_ever);
    std::move(theirs.begin(), theirs.end(), std::back_inserter(all));
    total.stored_energy += f.stored_energy;
    total.deepest_overlap = std::max(total.deepest_overlap, f.deepest_overlap);
    total.deepest_overlap_ever = std::max(total.deepest_overlap_ever, f.deepest_overlap_ever);
  }
  // One process's order: by body pair (the broad phase's), each pair's contacts as found
  // (a pair's contacts are all on the process that evaluated it).
  std::stable_sort(all.begin(), all.end(), [](const Contact& x, const Contact& y) {
    return std::pair(x.a, x.b) < std::pair(y.a, y.b);
  });
  contacts_.contacts() = std::move(all);
  solver_->set_figures(total);
}

}  // namespace sluice
