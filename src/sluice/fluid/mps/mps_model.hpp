// Moving Particle Semi-implicit method (seed 000; Koshizuka & Oka 1996). Each step: an
// explicit prediction (gravity, viscosity through the Laplacian model) moves the fluid; after
// the neighbour sort the particle number density n* finds the free surface; the pressure comes
// from the pressure Poisson equation (incompressible variant) or from n* through an equation
// of state (explicit variant); the pressure gradient corrects velocity and position.
// Walls and bodies are particles: their first layer (boundary particles) and the layers behind
// it (dummies) fill the number density; their pressures are extrapolated from the fluid (the
// default) or, for the first layer only, solved in rows of their own (pressure_equation.hpp).
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "sluice/exec/policy.hpp"
#include "sluice/fluid/mps/body_surface_pressure.hpp"
#include "sluice/fluid/mps/mps_operators.hpp"
#include "sluice/fluid/mps/mps_parameters.hpp"
#include "sluice/fluid/mps/pressure_equation.hpp"
#include "sluice/fluid/particle_fluid.hpp"

namespace sluice {

// What an MPS particle is: fluid, boundary (wall or body particle in the pressure equation) or
// dummy (behind the boundary, in the number density only).
enum MpsRole : std::int32_t { kMpsFluid = 0, kMpsBoundary = 1, kMpsDummy = 2 };

// A skin around r_e in the cell grid and neighbour list: the list built at the predicted
// positions still holds every neighbour after the pressure correction moves the particles.
inline constexpr Real kMpsSkin = 0.2;

template <int D>
class MpsModel final : public ParticleFluid<D> {
 public:
  MpsModel(const MpsParameters& parameters, const io::CaseConfig& config,
           const BodyGeometry& bodies)
      : ParticleFluid<D>(
            config,
            (std::max(parameters.re_over_dx, parameters.laplacian_re_over_dx) + kMpsSkin) *
                config.spacing,
            bodies),
        p_(parameters),
        density_(config.fluid.density),
        weight_{parameters.re_over_dx * config.spacing},
        laplacian_weight_{parameters.laplacian_re_over_dx * config.spacing},
        lattice_(full_lattice_constants<D>(config.spacing, weight_.re)),
        laplacian_lattice_(full_lattice_constants<D>(config.spacing, laplacian_weight_.re)),
        equation_(parameters.solver, parameters.solver_settings) {
    assign_roles(config, bodies);
  }

  std::string describe() const override {
    return fmt::format(
        "mps ({}): r_e = {:.4g} m ({} dx), n0 = {:.4g}, {}lambda = {:.4g} dx^2, beta = {}, "
        "gamma = {}, alpha = {:.3g} 1/Pa ({} form), negative pressure {}, wall pressure {}, "
        "gradient against the neighbourhood's smallest pressure from n* = {} n0, {}",
        explicit_variant() ? "explicit" : "incompressible", weight_.re, p_.re_over_dx, lattice_.n0,
        laplacian_weight_.re == weight_.re
            ? std::string()
            : fmt::format("Laplacian r_e = {} dx with n0 = {:.4g} and ", p_.laplacian_re_over_dx,
                          laplacian_lattice_.n0),
        laplacian_lattice_.lambda / (this->state().spacing * this->state().spacing),
        p_.surface_threshold, p_.source_relaxation, p_.compressibility,
        p_.pressure_memory ? "rate" : "ikeda", p_.keep_negative_pressure ? "kept" : "clamped",
        extrapolated_walls() ? "extrapolated" : "solved", p_.minimum_density,
        explicit_variant()
            ? fmt::format("c0 = {:.4g} m/s", p_.sound_speed)
            : fmt::format("solver {} (tolerance {:.3g})", p_.solver, p_.solver_settings.tolerance));
  }

  void initialize() override {
    auto& ps = this->state().particles;
    number_density_ = ps.add_scalar_field({"number_density", "1", true});
    surface_ = ps.add_int_field({"free_surface", "1", true});
    build_neighbours();
    find_surface();
    measure_extremes();
  }

  TimeStep next_time_step() const override {
    const ParticleState<D>& s = this->state();
    const Real l0 = s.spacing;
    TimeStep step;
    if (explicit_variant()) {
      step.tighten(p_.cfl * l0 / (p_.sound_speed + max_speed_),
                   "the speed of sound and the flow speed");
    } else {
      step.tighten(p_.cfl * l0 / std::max(max_speed_, p_.max_speed),
                   "the flow speed (at least model.max_speed, from gravity and depth)");
    }
    const Real nu = s.kinematic_viscosity +
                    (explicit_variant() ? p_.artificial_viscosity * p_.sound_speed * l0 : 0);
    if (nu > 0) step.tighten(0.125 * l0 * l0 / nu, "the viscosity");
    return step;
  }

  std::vector<std::pair<std::string, double>> counters() const override {
    if (explicit_variant()) return {};
    return {{"pressure_solves", static_cast<double>(solves_)},
            {"pressure_iterations_per_solve",
             solves_ > 0 ? static_cast<double>(iterations_) / static_cast<double>(solves_) : 0},
            {"pressure_unknowns_per_solve",
             solves_ > 0 ? static_cast<double>(unknowns_) / static_cast<double>(solves_) : 0}};
  }

  std::optional<std::string> check(const StepClock& clock) const override {
    if (failure_) return failure_;
    return ParticleFluid<D>::check(clock);
  }

  // For tests: the operators over the present neighbour list, and the last solve.
  MpsOperators<D> operators() const {
    return MpsOperators<D>(this->state().particles.position, neighbours_, weight_, lattice_,
                           laplacian_weight_, laplacian_lattice_, p_.gradient_correction);
  }
  const MpsLatticeConstants& lattice() const { return lattice_; }
  const PressureEquationReport& last_solve() const { return equation_.report(); }
  FieldHandle<std::int32_t> role_field() const { return role_; }

 protected:
  void archive_model(StateArchive& a) override {
    neighbours_.archive_state(a);  // the next step's prediction uses the last step's list
    a(max_speed_, failure_, solves_, iterations_, unknowns_);
  }

  void model_stages(StageList& before, StageList& after) override {
    before.push_back(
        make_stage<const StepClock>("predict", [this](const StepClock& c) { predict(c.dt); }));
    after.push_back(make_stage<const StepClock>("neighbour_list",
                                                [this](const StepClock&) { build_neighbours(); }));
    after.push_back(make_stage<const StepClock>("number_density",
                                                [this](const StepClock&) { find_surface(); }));
    if (explicit_variant()) {
      after.push_back(make_stage<const StepClock>(
          "state_equation", [this](const StepClock&) { pressure_from_density(); }));
    } else {
      after.push_back(make_stage<const StepClock>(
          "assembly", [this](const StepClock& c) { equation_.assemble(inputs(c.dt)); }));
      after.push_back(
          make_stage<const StepClock>("solve", [this](const StepClock& c) { solve(c); }));
    }
    after.push_back(make_stage<const StepClock>("correct", [this](const StepClock& c) {
      correct(c.dt);
      measure_extremes();
    }));
  }

  void body_point_forces(const std::vector<BodyKinematics>& motion,
                         std::vector<Vec3>& force) const override {
    const auto& ps = this->state().particles;
    const std::size_t points = this->body_points().size();
    std::vector<double> pressure(points, 0.0);
    std::vector<bool> wet(points, false);
    const auto& role = ps[role_];
    for (std::size_t i = 0; i < ps.size(); ++i) {
      const std::int32_t k = ps.body_point[i];
      if (k < 0 || role[i] != kMpsBoundary) continue;
      pressure[k] = ps.pressure[i];
      wet[k] = active_[i] != 0;
    }
    surface_pressure_.add_forces(pressure, wet, this->state().body_point_acceleration,
                                 to_3d<D>(this->state().gravity), density_,
                                 p_.keep_negative_pressure, motion, force);
  }

 private:
  bool explicit_variant() const { return p_.variant == MpsVariant::kExplicit; }
  bool extrapolated_walls() const {
    return !explicit_variant() && p_.wall_pressure == MpsWallPressure::kExtrapolated;
  }

  // Boundary particles are the wall and body particles within one spacing of the surface
  // (the layer dx/2 under it); the deeper ones are dummies.
  void assign_roles(const io::CaseConfig& config, const BodyGeometry& bodies) {
    auto& ps = this->state().particles;
    role_ = ps.add_int_field({"mps_role", "1", true});
    auto& role = ps[role_];
    const Real dx = config.spacing;
    const std::vector<BodyKinematics> motion = bodies.motion();
    std::vector<bool> boundary_point(this->body_points().size(), false);
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (ps.is_fluid(i)) {
        role[i] = kMpsFluid;
        continue;
      }
      const Vec3 x = to_3d<D>(ps.position[i]);
      const std::int32_t k = ps.body_point[i];
      const double depth = k >= 0 ? bodies.nearest_on_body(this->body_points()[k].body, x).distance
                                  : bodies.nearest_on_walls(x).distance;
      const bool boundary = depth > -dx;
      role[i] = boundary ? kMpsBoundary : kMpsDummy;
      if (k >= 0) boundary_point[k] = boundary;
    }
    surface_pressure_ = BodySurfacePressure(bodies, this->body_points(), boundary_point);
  }

  // Whether particle j takes part in the pressure equation's Laplacian and gradient: fluid,
  // and the wall particles that the fluid reaches (boundary ones; dummies too with
  // extrapolated walls).
  bool pressure_neighbour(std::size_t j) const { return active_[j] != 0; }

  // Rows for the fluid and for the wall particles that have fluid in the cells around them
  // (the boundary layer; with extrapolated walls the dummies too, whose pressures the fluid's
  // gradient reads). A prefix count of fluid over the cell-sorted particles answers that per
  // cell range: dry walls, most of a tall tank, cost nothing.
  void build_neighbours() {
    auto& s = this->state();
    const auto& ps = s.particles;
    const auto& role = ps[role_];
    fluid_before_.resize(ps.size() + 1);
    fluid_before_[0] = 0;
    for (std::size_t j = 0; j < ps.size(); ++j)
      fluid_before_[j + 1] = fluid_before_[j] + (ps.is_fluid(j) ? 1 : 0);
    neighbours_.build(ps.position, s.cells, s.cells.radius(), [&](std::size_t i) {
      if (role[i] == kMpsFluid) return true;
      if (role[i] == kMpsDummy && !extrapolated_walls()) return false;
      bool wet = false;
      s.cells.for_each_candidate_range(ps.position[i], [&](std::uint32_t begin, std::uint32_t end) {
        wet = wet || fluid_before_[end] > fluid_before_[begin];
      });
      return wet;
    });
  }

  // u* = u + dt (g + nu lap u), x* = x + dt u*. Walls and bodies are no-slip: their own
  // velocities enter the viscous Laplacian. Then the collisions.
  void predict(Real dt) {
    auto& s = this->state();
    auto& ps = s.particles;
    const MpsOperators<D> op = operators();
    const auto& role = ps[role_];
    // The explicit variant's pressure waves need damping: an artificial viscosity
    // alpha c0 l0 on top of the fluid's own.
    const Real nu = s.kinematic_viscosity +
                    (explicit_variant() ? p_.artificial_viscosity * p_.sound_speed * s.spacing : 0);
    velocity_scratch_.resize(ps.size());
    exec::Default::for_each_balanced(ps.size(), [&](std::size_t i) {
      velocity_scratch_[i] = ps.velocity[i];
      if (!ps.is_fluid(i)) return;
      Vec<D> a = s.gravity;
      if (nu > 0) {
        a += nu * op.laplacian(i, ps.velocity, [&](std::size_t j) { return role[j] != kMpsDummy; });
      }
      velocity_scratch_[i] += dt * a;
    });
    exec::Default::for_each(ps.size(), [&](std::size_t i) {
      if (!ps.is_fluid(i)) return;
      ps.velocity[i] = velocity_scratch_[i];
      ps.position[i] += dt * ps.velocity[i];
    });
    collide(dt);
  }

  // Fluid particles closer than collision_distance l0 that approach each other exchange the
  // approaching part of their relative velocity with restitution e (Koshizuka et al. 1998;
  // Lee et al. 2011): a guard against the clustering that MPS's pressure cannot resolve.
  // Walls and bodies count as infinitely heavy. Each particle gathers its own change.
  void collide(Real dt) {
    if (p_.collision_distance <= 0) return;
    auto& ps = this->state().particles;
    const auto& role = ps[role_];
    const Real reach = p_.collision_distance * this->state().spacing;
    const Real reach2 = reach * reach;
    const Real e = p_.collision_restitution;
    exec::Default::for_each_balanced(ps.size(), [&](std::size_t i) {
      velocity_scratch_[i] = Vec<D>::Zero();
      if (!ps.is_fluid(i)) return;
      Vec<D> change = Vec<D>::Zero();
      neighbours_.for_each(i, [&](std::size_t j) {
        if (role[j] == kMpsDummy) return;
        const Vec<D> r = ps.position[j] - ps.position[i];
        const Real r2 = r.squaredNorm();
        if (r2 >= reach2 || r2 <= 0) return;
        const Vec<D> normal = r / std::sqrt(r2);
        const Real approach = (ps.velocity[i] - ps.velocity[j]).dot(normal);
        if (approach <= 0) return;
        const Real share = ps.is_fluid(j) ? 0.5 : 1.0;  // equal masses, or a wall
        change -= share * (1 + e) * approach * normal;
      });
      velocity_scratch_[i] = change;
    });
    exec::Default::for_each(ps.size(), [&](std::size_t i) {
      if (!ps.is_fluid(i)) return;
      ps.velocity[i] += velocity_scratch_[i];
      ps.position[i] += dt * velocity_scratch_[i];
    });
  }

  // Number density n*, and the free surface: n* < beta n0, confirmed by fewer neighbours than
  // surface_count_ratio of a full lattice's (Tanaka & Masunaga 2010), so that an inner particle
  // whose density dips is not taken for a surface one. Wall particles that no fluid particle
  // reaches are inactive: no pressure, and out of the fluid's operators.
  void find_surface() {
    auto& ps = this->state().particles;
    const MpsOperators<D> op = operators();
    const auto& role = ps[role_];
    auto& n = ps[number_density_];
    auto& surface = ps[surface_];
    active_.assign(ps.size(), 0);
    const Real dense = p_.surface_threshold * lattice_.n0;
    const Real crowded = p_.surface_count_ratio * lattice_.neighbours;
    const auto all = [](std::size_t) { return true; };
    exec::Default::for_each_balanced(ps.size(), [&](std::size_t i) {
      surface[i] = 0;
      n[i] = 0;
      if (role[i] == kMpsDummy && !extrapolated_walls()) return;
      int count = 0;
      n[i] = op.number_density(i, all, count);
      surface[i] = (n[i] < dense && count < crowded) ? 1 : 0;
      bool reached = role[i] == kMpsFluid;
      if (!reached) {
        op.number_density(
            i, [&](std::size_t j) { return role[j] == kMpsFluid; }, count);
        reached = count > 0;
      }
      active_[i] = reached ? 1 : 0;
    });
  }

  PressureEquationInputs<D> inputs(Real dt) {
    const auto& s = this->state();
    const auto& ps = s.particles;
    if (extrapolated_walls()) {
      // Each wall and body particle: whether the fluid reaches it, g - a_w, and its velocity
      // carried on by dt (g - a_w) for the fluid's divergence (pressure_equation.hpp).
      extrapolated_.assign(ps.size(), 0);
      wall_gravity_.assign(ps.size(), Vec<D>::Zero());
      source_velocity_ = ps.velocity;
      exec::Default::for_each(ps.size(), [&](std::size_t i) {
        if (ps.is_fluid(i)) return;
        extrapolated_[i] = active_[i];
        const std::int32_t k = ps.body_point[i];
        Vec<D> g = s.gravity;
        if (k >= 0) g -= from_3d<D>(s.body_point_acceleration[static_cast<std::size_t>(k)]);
        wall_gravity_[i] = g;
        source_velocity_[i] += dt * g;
      });
    }
    PressureEquationInputs<D> in{operators(),
                                 extrapolated_walls() ? source_velocity_ : ps.velocity,
                                 ps[number_density_],
                                 ps[surface_],
                                 active_,
                                 ps.pressure};
    in.dt = dt;
    in.density = density_;
    in.relaxation = p_.source_relaxation;
    in.compressibility = p_.compressibility;
    in.pressure_memory = p_.pressure_memory;
    if (extrapolated_walls()) {
      in.extrapolated = &extrapolated_;
      in.wall_gravity = &wall_gravity_;
    }
    return in;
  }

  void solve(const StepClock& clock) {
    auto& ps = this->state().particles;
    const bool solved = equation_.solve(ps.pressure);
    const PressureEquationReport& r = equation_.report();
    ++solves_;
    iterations_ += r.iterations;
    unknowns_ += r.unknowns;
    if (!solved && !failure_) {
      failure_ = fmt::format(
          "the pressure solve ({}) did not reach its tolerance {:.3g} at step {}, t = {:.6g} s: "
          "relative residual {:.3g} after {} iterations ({} unknowns); raise "
          "model.solver_max_iterations or model.solver_tolerance, or choose another "
          "model.solver",
          p_.solver, p_.solver_settings.tolerance, clock.step, clock.time, r.relative_residual,
          r.iterations, r.unknowns);
    }
    clamp_negative();
  }

  // Explicit variant: p = c0^2 rho0 (n* - n0) / n0 (Shakibaeinia & Jin 2010), zero on the
  // surface and on inactive boundary particles.
  void pressure_from_density() {
    auto& ps = this->state().particles;
    const auto& n = ps[number_density_];
    const auto& surface = ps[surface_];
    const Real stiffness = p_.sound_speed * p_.sound_speed * density_ / lattice_.n0;
    exec::Default::for_each(ps.size(), [&](std::size_t i) {
      const bool free = active_[i] == 0 || surface[i] != 0;
      ps.pressure[i] = free ? 0 : stiffness * (n[i] - lattice_.n0);
    });
    clamp_negative();
  }

  void clamp_negative() {
    if (p_.keep_negative_pressure) return;
    auto& ps = this->state().particles;
    exec::Default::for_each(
        ps.size(), [&](std::size_t i) { ps.pressure[i] = std::max<Real>(ps.pressure[i], 0); });
  }

  // u = u* - dt / rho grad p, x = x* + dt (u - u*).
  void correct(Real dt) {
    auto& ps = this->state().particles;
    const MpsOperators<D> op = operators();
    const auto& surface = ps[surface_];
    const Real scale = dt / density_;
    const auto& n = ps[number_density_];
    const Real full = p_.minimum_density * lattice_.n0;
    velocity_scratch_.resize(ps.size());
    exec::Default::for_each_balanced(ps.size(), [&](std::size_t i) {
      if (!ps.is_fluid(i)) return;
      velocity_scratch_[i] =
          -scale * op.gradient(
                       i, ps.pressure, [&](std::size_t j) { return pressure_neighbour(j); },
                       surface[i] != 0, !(n[i] < full));
    });
    exec::Default::for_each(ps.size(), [&](std::size_t i) {
      if (!ps.is_fluid(i)) return;
      ps.velocity[i] += velocity_scratch_[i];
      ps.position[i] += dt * velocity_scratch_[i];
    });
  }

  void measure_extremes() {
    const auto& ps = this->state().particles;
    max_speed_ = exec::Default::max_of(
        ps.size(), [&](std::size_t i) { return ps.is_fluid(i) ? ps.velocity[i].norm() : 0.0; });
  }

  MpsParameters p_;
  Real density_;
  MpsWeight weight_, laplacian_weight_;
  MpsLatticeConstants lattice_, laplacian_lattice_;
  PressureEquation<D> equation_;
  NeighbourList<D> neighbours_;
  BodySurfacePressure surface_pressure_;
  FieldHandle<std::int32_t> role_, surface_;
  FieldHandle<Real> number_density_;
  std::vector<std::uint8_t> active_, extrapolated_;
  std::vector<std::uint32_t> fluid_before_;  // fluid among particles [0, k), cell-sorted  // per
                                             // particle, valid from the number density stage on
  std::vector<Vec<D>> velocity_scratch_;
  std::vector<Vec<D>> wall_gravity_, source_velocity_;  // per particle, extrapolated walls
  Real max_speed_ = 0;
  std::optional<std::string> failure_;
  long solves_ = 0, iterations_ = 0, unknowns_ = 0;
};

}  // namespace sluice
