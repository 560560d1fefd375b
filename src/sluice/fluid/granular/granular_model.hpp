// Water as many frictionless rigid spheres (seed 001's fourth method; Mazhar, Heyn, Negrut &
// Tasora 2015): each fluid block is filled with spheres on the lattice of the case's spacing,
// each carrying the water of its lattice cell (mass rho dx^D, so the lattice has the water's
// density). Every step the spheres, the walls and the case's bodies meet in one cone
// complementarity problem (the rigid system's velocity-level step; this model joins it as a
// participant, the monolithic coupling): sphere-sphere and sphere-wall contacts in a compact
// group of their own, sphere-body contacts as rows on the bodies. Optional friction and
// cohesion. The spheres then move with their new velocities. Each sphere's `pressure` is the
// mean normal stress its contacts put on the cell it stands for (virial: the radius times the
// sum of its normal contact forces over D dx^D).
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <unordered_map>

#include "sluice/ccp/contact_rows.hpp"
#include "sluice/ccp/row_group.hpp"
#include "sluice/ccp/sphere_contacts.hpp"
#include "sluice/contact/point_grid.hpp"
#include "sluice/exec/policy.hpp"
#include "sluice/fluid/granular/granular_parameters.hpp"
#include "sluice/fluid/granular/sphere_walls.hpp"
#include "sluice/fluid/monolithic_case.hpp"
#include "sluice/fluid/monolithic_solve.hpp"
#include "sluice/fluid/particle_fluid.hpp"

namespace sluice {

template <int D>
class GranularModel final : public ParticleFluid<D> {
 public:
  GranularModel(const GranularParameters& parameters, const io::CaseConfig& config,
                const BodyGeometry& bodies)
      // The spheres meet the walls' surfaces (sphere_walls.hpp): no wall particle.
      : ParticleFluid<D>(config, parameters.radius * (2 + parameters.envelope), bodies,
                         ParticleFluid<D>::Walls::kSurfacesOnly),
        p_(parameters),
        config_(config),
        bodies_(&bodies),
        walls_(config.walls, config.dimension),
        mass_(config.fluid.density * std::pow(config.spacing, D)),
        // A sphere's inertia over m r^2 (2D: a disc's, per unit depth as its mass).
        inertia_factor_(D == 3 ? 0.4 : 0.5),
        solve_(parameters.emulated_device) {}

  std::string describe() const override {
    return fmt::format(
        "granular: spheres of r = {:.4g} m and {:.4g} kg ({} water per lattice cell), friction "
        "{}, cohesion {} N, {}{}",
        p_.radius, mass_, D == 3 ? "the" : "the 2D", p_.friction, p_.cohesion,
        p_.time_step > 0 ? fmt::format("fixed dt = {} s", p_.time_step)
                         : fmt::format("dt = {} r / max speed", p_.cfl),
        p_.emulated_device ? ", " + solve_.where() : "");
  }

  void initialize() override {
    auto& ps = this->state().particles;
    id_ = ps.add_int_field({"sphere_id", "1"});
    for (int k = 0; k < 3; ++k) spin_[k] = ps.add_scalar_field({spin_names[k], "rad/s"});
    radius_field_ = ps.add_scalar_field({"radius", "m", true});
    std::int32_t next = 0;
    // Each seed's stream starts 2^40 numbers after the last one's: disjoint for any packing.
    const std::uint64_t stream = std::uint64_t(p_.packing_seed) << 40;
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (!ps.is_fluid(i)) continue;
      const Real r =
          p_.radius * (1 - p_.size_spread * unit_random(stream + std::uint64_t(next) * 3 + 2));
      const Real room = p_.jitter * (0.5 * config_.spacing - r);
      // Sideways by up to `room` in each horizontal direction, from the sphere's number alone.
      for (int a = 0; a + 1 < D; ++a) {
        ps.position[i][a] += room * (2 * unit_random(stream + std::uint64_t(next) * 3 + a) - 1);
      }
      ps.mass[i] = mass_;
      ps.pressure[i] = 0;
      ps[id_][i] = next++;
      ps[radius_field_][i] = r;
    }
    spheres_ = static_cast<std::size_t>(next);
  }

  // A sphere moves at most cfl radii a step: at its speed, or falling from rest.
  TimeStep next_time_step() const override {
    TimeStep step;
    if (p_.time_step > 0) {
      step.tighten(p_.time_step, "model.time_step");
      return step;
    }
    const double travel = p_.cfl * p_.radius;
    const double g = this->state().gravity.norm();
    if (max_speed_ > 0) step.tighten(travel / max_speed_, "the spheres' speed");
    if (g > 0) step.tighten(std::sqrt(2 * travel / g), "gravity");
    step.tighten(travel / (0.01 * p_.max_speed), "a hundredth of model.max_speed");
    return step;
  }

  // The spheres as bodies after the rigid ones, with gravity in their predicted velocity, and
  // their contacts with each other, the walls and the bodies.
  void add_to_problem(CcpProblem& problem, double h) override {
    const auto& ps = this->state().particles;
    first_ = problem.bodies.size();
    sphere_particle_.clear();
    sphere_of_.assign(ps.size(), -1);
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (!ps.is_fluid(i)) continue;
      sphere_of_[i] = static_cast<std::int32_t>(sphere_particle_.size());
      sphere_particle_.push_back(static_cast<std::uint32_t>(i));
    }
    const Vec3 gravity = to_3d<D>(this->state().gravity);
    const std::uint8_t locks = D == 2 ? kLockPlanar : 0;
    for (const std::uint32_t i : sphere_particle_) {
      problem.bodies.add(to_3d<D>(ps.velocity[i]) + h * gravity, spin(i), 1 / mass_, 1 / inertia(i),
                         locks);
    }
    gravity_step_ = gravity.norm() * h;
    sphere_contacts_.begin(first_, sphere_particle_.size(), spheres_, p_.friction, p_.cohesion * h,
                           p_.rolling_friction);
    find_sphere_contacts(h);
    find_wall_contacts(h);
    sphere_contacts_.finish();
    problem.add(sphere_contacts_);
    find_body_contacts(h);
    problem.add(body_rows_);
  }

  CcpResult solve(CcpProblem& problem, const CcpSettings& settings,
                  BodyVelocities& velocities) override {
    return solve_(problem, settings, velocities);
  }

  void take_solution(const CcpProblem&, const BodyVelocities& u, double h) override {
    auto& ps = this->state().particles;
    exec::Default::for_each(sphere_particle_.size(), [&](std::size_t s) {
      const std::uint32_t i = sphere_particle_[s];
      ps.velocity[i] = from_3d<D>(u.linear[first_ + s]);
      for (int k = 0; k < 3; ++k) ps[spin_[k]][i] = u.angular[first_ + s][k];
      ps.position[i] += h * ps.velocity[i];
    });
    gather_loads(h);
    max_speed_ = exec::Default::max_of(sphere_particle_.size(), [&](std::size_t s) {
      return ps.velocity[sphere_particle_[s]].norm();
    });
    ++steps_;
  }

  std::vector<Wrench> body_loads(const std::vector<BodyKinematics>& motion) const override {
    return loads_of_solve(body_load_, motion.size());
  }

  std::vector<std::pair<std::string, double>> counters() const override {
    const double steps = std::max<double>(1, double(steps_));
    std::vector<std::pair<std::string, double>> out{
        {"sphere_contacts_per_step", double(sphere_contact_total_) / steps},
        {"body_contacts_per_step", double(body_contact_total_) / steps}};
    // The device's copy of the problem, per particle of the set (walls and bodies' too).
    if (solve_.on_device()) {
      out.emplace_back("device_bytes_per_particle",
                       double(solve_.largest_bytes()) /
                           std::max<double>(1, double(this->state().particles.size())));
    }
    return out;
  }

  FluidEnergy energy() const override {
    FluidEnergy e = ParticleFluid<D>::energy();
    const auto& ps = this->state().particles;
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (ps.is_fluid(i)) e.kinetic += 0.5 * inertia(i) * spin(i).squaredNorm();
    }
    return e;
  }

  // The radius of sphere particle i.
  Real radius_of(std::size_t i) const { return this->state().particles[radius_field_][i]; }
  const SphereContacts& sphere_contacts() const { return sphere_contacts_; }

 protected:
  void model_stages(StageList&, StageList&) override {}
  // The warm starts of the sphere and body contacts; the fastest speed of the last solve (the
  // wall correction after it may slow a sphere, so it is not the present one).
  void archive_model(StateArchive& a) override {
    a(sphere_contacts_, last_body_impulse_, max_speed_);
    a(steps_, sphere_contact_total_, body_contact_total_);
  }
  // The loads come from the solve (body_loads), not from the body particles.
  void body_point_forces(const std::vector<BodyKinematics>&, std::vector<Vec3>&) const override {}

 private:
  static constexpr const char* spin_names[3] = {"spin_x", "spin_y", "spin_z"};

  // A number in [0, 1) from an integer (SplitMix64, Steele, Lea & Flood 2014): the same on
  // every machine.
  static Real unit_random(std::uint64_t k) {
    std::uint64_t z = k + 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return Real(z >> 11) * 0x1.0p-53;
  }

  Real inertia(std::size_t i) const {
    const Real r = this->state().particles[radius_field_][i];
    return inertia_factor_ * mass_ * r * r;
  }

  Vec3 spin(std::size_t i) const {
    const auto& ps = this->state().particles;
    return Vec3(ps[spin_[0]][i], ps[spin_[1]][i], ps[spin_[2]][i]);
  }

  // The least normal velocity of a contact with this gap: a gap may close within the step; an
  // overlap is pushed apart at up to the recovery speed.
  Real target(Real gap, Real h) const {
    return std::min(-gap / h, config_.contact.velocity_step.recovery_speed);
  }

  // Pairs of spheres closer than the envelope, oriented from the smaller identity, in sphere
  // order (each block of spheres collects its pairs, the blocks joined in order).
  void find_sphere_contacts(Real h) {
    const ParticleState<D>& s = this->state();
    const auto& ps = s.particles;
    const Real reach = p_.radius * (2 + p_.envelope);
    constexpr std::size_t kBlock = 2048;
    const std::size_t n = sphere_particle_.size();
    const std::size_t blocks = (n + kBlock - 1) / kBlock;
    block_contacts_.resize(blocks);
    exec::Default::for_each_balanced(blocks, [&](std::size_t k) {
      auto& out = block_contacts_[k];
      out.clear();
      for (std::size_t a = k * kBlock; a < std::min(n, (k + 1) * kBlock); ++a) {
        const std::uint32_t i = sphere_particle_[a];
        s.cells.for_each_neighbor(
            ps.position, i, reach * reach, [&](std::size_t j, const Vec<D>& rij, Real r2) {
              const std::int32_t b = sphere_of_[j];
              if (b <= std::int32_t(a)) return;  // walls, bodies, and each pair once
              const Real distance = std::sqrt(r2);
              SphereContacts::Contact c;
              const bool forward = ps[id_][i] < ps[id_][j];
              const std::size_t from = forward ? a : std::size_t(b);
              const std::size_t to = forward ? std::size_t(b) : a;
              c.a = std::uint32_t(first_ + from);
              c.b = std::uint32_t(first_ + to);
              c.owner = std::uint32_t(std::min(ps[id_][i], ps[id_][j]));
              c.partner = std::uint32_t(std::max(ps[id_][i], ps[id_][j]));
              // rij = x_i - x_j: from j to i.
              const Vec3 n_ji = to_3d<D>(rij) / distance;
              c.normal = forward ? Vec3(-n_ji) : n_ji;
              c.radius_a = ps[radius_field_][forward ? i : j];
              c.radius_b = ps[radius_field_][forward ? j : i];
              c.target = target(distance - c.radius_a - c.radius_b, h);
              // Restitution: an impact (faster than gravity brings in a step) rebounds.
              const Real approach = -c.normal.dot(
                  to_3d<D>(ps.velocity[forward ? j : i] - ps.velocity[forward ? i : j]));
              if (p_.restitution > 0 && approach > 2 * gravity_step_) {
                c.target = std::max(c.target, p_.restitution * approach);
              }
              out.push_back(c);
            });
      }
    });
    auto& contacts = sphere_contacts_.contacts();
    for (const auto& block : block_contacts_)
      contacts.insert(contacts.end(), block.begin(), block.end());
    sphere_contact_total_ += contacts.size();
  }

  void find_wall_contacts(Real h) {
    const auto& ps = this->state().particles;
    const Real reach = p_.radius * (1 + p_.envelope);
    auto& contacts = sphere_contacts_.contacts();
    for (std::size_t s = 0; s < sphere_particle_.size(); ++s) {
      const std::uint32_t i = sphere_particle_[s];
      const Vec3 x = to_3d<D>(ps.position[i]);
      for (std::size_t w = 0; w < walls_.size(); ++w) {
        const SurfacePoint p = walls_.nearest(w, x);
        if (p.distance >= reach) continue;
        SphereContacts::Contact c;
        c.a = SphereContacts::kWorld;
        c.b = std::uint32_t(first_ + s);
        c.owner = std::uint32_t(ps[id_][i]);
        c.partner = SphereContacts::wall_code(std::uint32_t(w));
        c.normal = p.normal;
        c.radius_b = ps[radius_field_][i];
        c.target = target(p.distance - c.radius_b, h);
        contacts.push_back(c);
      }
    }
  }

  // Each body's contacts with the spheres within its reach, as cones (or, frictionless, single
  // rows) on the body (problem body b) and the sphere, warm-started by (body, sphere).
  void find_body_contacts(Real h) {
    body_rows_.clear();
    body_row_keys_.clear();
    const std::size_t bodies = bodies_->body_count();
    if (bodies == 0) return;
    const auto& ps = this->state().particles;
    // Each body's box, from its particles (under its surface: grown by a spacing).
    std::vector<AxisBox> boxes(bodies, AxisBox::empty());
    for (std::size_t i = 0; i < ps.size(); ++i) {
      const std::int32_t k = ps.body_point[i];
      if (k < 0) continue;
      boxes[this->body_points()[std::size_t(k)].body].grow(to_3d<D>(ps.position[i]));
    }
    const std::vector<BodyKinematics> motion = bodies_->motion();
    const Real reach = p_.radius * (1 + p_.envelope);
    // The spheres in cells (contact/'s point grid): a body meets those in the cells its box
    // covers, not every sphere of the pool.
    sphere_centre_.resize(sphere_particle_.size());
    for (std::size_t s = 0; s < sphere_particle_.size(); ++s)
      sphere_centre_[s] = to_3d<D>(ps.position[sphere_particle_[s]]);
    sphere_grid_.build(sphere_centre_, nullptr, 4 * p_.radius);
    for (std::size_t b = 0; b < bodies; ++b) {
      // The way the body can travel towards a sphere in the step, on top of the envelope.
      const Real margin = reach + config_.spacing + 2 * motion[b].velocity.norm() * h;
      const Real mu = std::min(p_.friction, config_.bodies[b].material.friction);
      if (boxes[b].min[0] > boxes[b].max[0]) continue;  // no particle: no sphere within its box
      spheres_near(boxes[b], margin);
      for (const std::uint32_t s : near_) {
        const std::uint32_t i = sphere_particle_[s];
        const Vec3 x = to_3d<D>(ps.position[i]);
        if (!boxes[b].contains_within(x, margin)) continue;
        const SurfacePoint p = bodies_->nearest_on_body(b, x);
        if (p.distance - ps[radius_field_][i] >=
            p_.envelope * p_.radius + 2 * motion[b].velocity.norm() * h)
          continue;
        add_body_contact(b, s, p, mu, h);
      }
    }
    body_contact_total_ += body_row_keys_.size();
  }

  // The spheres (their indices among the spheres, increasing, as a scan of all would find
  // them) in the grid's cells that `box` grown by `margin` covers; all of them where the box
  // covers more cells than there are spheres.
  void spheres_near(const AxisBox& box, Real margin) {
    near_.clear();
    const Vec3 lo = box.min.array() - margin, hi = box.max.array() + margin;
    if (sphere_grid_.cells_in(lo, hi) > double(sphere_particle_.size())) {
      for (std::uint32_t s = 0; s < sphere_particle_.size(); ++s) near_.push_back(s);
      return;
    }
    sphere_grid_.for_each_in_cells(lo, hi, [&](std::uint32_t s) { near_.push_back(s); });
    std::sort(near_.begin(), near_.end());
  }

  void add_body_contact(std::size_t b, std::size_t s, const SurfacePoint& p, Real mu, Real h) {
    const auto& ps = this->state().particles;
    const Real r = ps[radius_field_][sphere_particle_[s]];
    // The body is a, the sphere b; the sphere's arm reaches its surface along the normal.
    std::array<ConstraintRow, 3> rows = contact_rows(
        b, first_ + s, p.normal, p.closest - bodies_->motion()[b].position, -r * p.normal);
    rows[0].bias = target(p.distance - r, h);
    rows[0].lower = -p_.cohesion * h;
    const std::uint64_t key =
        (std::uint64_t(b) << 32) | std::uint32_t(ps[id_][sphere_particle_[s]]);
    if (const auto found = last_body_impulse_.find(key); found != last_body_impulse_.end()) {
      for (int k = 0; k < 3; ++k) rows[k].impulse = found->second[std::size_t(k)];
    }
    if (mu > 0 || p_.cohesion > 0) {
      body_rows_.add_cone(rows[0], rows[1], rows[2], mu, p_.cohesion * h, key);
    } else {
      body_rows_.add_row(rows[0]);
    }
    body_row_keys_.push_back(key);
  }

  // After the solve: the bodies' loads over the step (for the output), the body rows'
  // impulses for the next warm start, and each sphere's contact pressure.
  void gather_loads(Real h) {
    auto& ps = this->state().particles;
    const std::size_t bodies = bodies_->body_count();
    body_load_.assign(bodies, Wrench{});
    std::vector<Real> normal_force(sphere_particle_.size(), 0);
    const auto& rows = body_rows_.rows();
    last_body_impulse_.clear();
    const std::size_t per = rows.size() == body_row_keys_.size() ? 1 : 3;
    for (std::size_t k = 0; k < body_row_keys_.size(); ++k) {
      std::array<Real, 3> impulses{};
      for (std::size_t r = 0; r < per; ++r) {
        const ConstraintRow& row = rows[k * per + r];
        impulses[r] = row.impulse;
        body_load_[row.a].force += row.impulse / h * row.linear_a;
        body_load_[row.a].moment += row.impulse / h * row.angular_a;
      }
      last_body_impulse_[body_row_keys_[k]] = impulses;
      normal_force[rows[k * per].b - first_] += std::abs(rows[k * per].impulse) / h;
    }
    const auto& contacts = sphere_contacts_.contacts();
    for (std::size_t c = 0; c < contacts.size(); ++c) {
      const Real f = std::abs(sphere_contacts_.normal_impulse(c)) / h;
      if (contacts[c].a != SphereContacts::kWorld) normal_force[contacts[c].a - first_] += f;
      normal_force[contacts[c].b - first_] += f;
    }
    const Real cell = D * std::pow(config_.spacing, D);
    for (std::size_t s = 0; s < sphere_particle_.size(); ++s) {
      const std::uint32_t i = sphere_particle_[s];
      ps.pressure[i] = ps[radius_field_][i] * normal_force[s] / cell;
    }
  }

  GranularParameters p_;
  io::CaseConfig config_;
  const BodyGeometry* bodies_;
  SphereWalls walls_;
  Real mass_, inertia_factor_;
  MonolithicSolve solve_;
  FieldHandle<std::int32_t> id_;
  FieldHandle<Real> spin_[3], radius_field_;
  std::size_t spheres_ = 0, first_ = 0;
  std::vector<std::uint32_t> sphere_particle_;  // sphere -> particle, this step
  std::vector<std::int32_t> sphere_of_;         // particle -> sphere (-1: not a sphere)
  SphereContacts sphere_contacts_;
  std::vector<Vec3> sphere_centre_;  // scratch of find_body_contacts
  PointGrid sphere_grid_;
  std::vector<std::uint32_t> near_;
  std::vector<std::vector<SphereContacts::Contact>> block_contacts_;
  RowGroup body_rows_;
  std::vector<std::uint64_t> body_row_keys_;
  std::unordered_map<std::uint64_t, std::array<Real, 3>> last_body_impulse_;
  std::vector<Wrench> body_load_;
  Real max_speed_ = 0;
  Real gravity_step_ = 0;  // g h: what gravity brings a resting contact in a step [m/s]
  long steps_ = 0;
  long sphere_contact_total_ = 0, body_contact_total_ = 0;
};

}  // namespace sluice
