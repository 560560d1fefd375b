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
#include "sluice/fluid/fluid_vector_norm.hpp"
#include "sluice/fluid/mps/body_surface_pressure.hpp"
#include "sluice/fluid/mps/mps_device_run.hpp"
#include "sluice/fluid/mps/mps_loop_bodies.hpp"
#include "sluice/fluid/mps/mps_operators.hpp"
#include "sluice/fluid/mps/mps_parameters.hpp"
#include "sluice/fluid/mps/neighbour_list.hpp"
#include "sluice/fluid/mps/pressure_equation.hpp"
#include "sluice/fluid/particle_fluid.hpp"

namespace sluice {

// A skin around r_e in the cell grid and neighbour list: the list built at the predicted
// positions still holds every neighbour after the pressure correction moves the particles.
inline constexpr Real kMpsSkin = 0.2;

template <int D>
class MpsModel final : public ParticleFluid<D> {
 public:
  // With `ranks` split, the pressure equation is split over them (the factory splits the
  // particles before initialize()).
  MpsModel(const MpsParameters& parameters, const io::CaseConfig& config,
           const BodyGeometry& bodies, const Communicator& ranks = Communicator::alone())
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
        equation_(parameters.solver, parameters.solver_settings, ranks) {
    assign_roles(config, bodies);
  }

  std::string describe() const override {
    std::string out = fmt::format(
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
    if (device_) {
      out += fmt::format(", on {} ({:.0f} bytes per particle there)", device_->name(),
                         device_->bytes_per_particle());
    }
    return out;
  }

  void initialize() override {
    auto& ps = this->state().particles;
    number_density_ = ps.add_scalar_field({"number_density", "1", true});
    surface_ = ps.add_int_field({"free_surface", "1", true});
    build_neighbours();
    find_surface();
    measure_extremes();
    if (p_.emulated_device) start_device();
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
    std::vector<std::pair<std::string, double>> out;
    if (!explicit_variant()) {
      out = {{"pressure_solves", static_cast<double>(solves_)},
             {"pressure_iterations_per_solve",
              solves_ > 0 ? static_cast<double>(iterations_) / static_cast<double>(solves_) : 0},
             {"pressure_unknowns_per_solve",
              solves_ > 0 ? static_cast<double>(unknowns_) / static_cast<double>(solves_) : 0}};
    }
    for (auto& entry : ParticleFluid<D>::counters()) out.push_back(std::move(entry));  // split
    return out;
  }

  std::optional<std::string> check(const StepClock& clock) const override {
    if (failure_) return failure_;
    return ParticleFluid<D>::check(clock);
  }

  // For tests: the operators over the present neighbour list, and the last solve.
  MpsOperators<D> operators() const {
    return MpsOperators<D>(this->state().particles.position.data(), neighbours_.view(), weight_,
                           lattice_, laplacian_weight_, laplacian_lattice_, p_.gradient_correction);
  }
  const MpsLatticeConstants& lattice() const { return lattice_; }
  const PressureEquationReport& last_solve() const {
    return device_ ? device_->report() : equation_.report();
  }
  FieldHandle<std::int32_t> role_field() const { return role_; }

 protected:
  void archive_model(StateArchive& a) override {
    // The next step's prediction uses the last step's list.
    if (device_ && !a.reading()) {
      std::vector<std::uint32_t> start, index;
      device_->download_neighbours(start, index);
      neighbours_.assign(std::move(start), std::move(index));
    }
    neighbours_.archive_state(a);
    if (device_ && a.reading())
      device_->upload_neighbours(neighbours_.starts(), neighbours_.indices());
    a(max_speed_, failure_, solves_, iterations_, unknowns_);
  }
  // The solves' counts are the whole run's on every rank; the list is drawn anew.
  void gather_model(StateArchive& a, bool first) override {
    NeighbourList<D> piece_list;
    piece_list.archive_state(a);
    Real speed = 0;
    std::optional<std::string> failure;
    a(speed, failure, solves_, iterations_, unknowns_);
    max_speed_ = first ? speed : std::max(max_speed_, speed);
    if (first) failure_.reset();
    if (!failure_) failure_ = failure;
  }
  // The next step's prediction reads the last step's list: the same neighbours, drawn here from
  // where the particles stand (a checkpoint on as many ranks keeps the list itself).
  void redistributed() override { build_neighbours(); }
  // At the open boundaries: a buffer particle that became fluid takes the fluid's role, fluid
  // that entered an outlet's buffer a boundary particle's (its pressure then extrapolated, or
  // prescribed where the outlet gives one).
  void handed_over(const BufferHandOver& hand_over) override {
    auto& role = this->state().particles[role_];
    for (const std::uint32_t i : hand_over.joined) role[i] = kMpsFluid;
    for (const std::uint32_t i : hand_over.left) role[i] = kMpsBoundary;
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
      after.push_back(
          make_stage<const StepClock>("assembly", [this](const StepClock& c) { assemble(c.dt); }));
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
    // On a device the host's set is fresh (the base refreshed it); the activity is the run's.
    std::vector<std::uint8_t> device_active;
    if (device_) device_->download_active(device_active);
    const std::vector<std::uint8_t>& active = device_ ? device_active : active_;
    for (std::size_t i = 0; i < ps.size(); ++i) {
      const std::int32_t k = ps.body_point[i];
      if (k < 0 || role[i] != kMpsBoundary) continue;
      pressure[k] = ps.pressure[i];
      wet[k] = active[i] != 0;
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
    if (device_) return this->on_device([&] { device_->build_neighbours(); });
    auto& s = this->state();
    const auto& ps = s.particles;
    const auto& role = ps[role_];
    fluid_before_.resize(ps.size() + 1);
    fluid_before_[0] = 0;
    for (std::size_t j = 0; j < ps.size(); ++j)
      fluid_before_[j + 1] = fluid_before_[j] + (ps.is_fluid(j) ? 1 : 0);
    const MpsListed<D> listed{role.data(), ps.position.front().data(), s.cells.view(),
                              fluid_before_.data(), extrapolated_walls()};
    neighbours_.build(ps.position, s.cells, s.cells.radius(), listed);
  }

  // The arrays of the host's particle set and the model's own, as the loop bodies see them
  // (mps_loop_bodies.hpp); the model's per-particle arrays sized to the set.
  MpsArrays<D> arrays() {
    auto& ps = this->state().particles;
    active_.resize(ps.size());
    velocity_scratch_.resize(ps.size());
    MpsArrays<D> a;
    a.position = ps.position.data();
    a.velocity = ps.velocity.data();
    a.pressure = ps.pressure.data();
    a.kind = reinterpret_cast<const std::int32_t*>(ps.kind.data());
    a.body_point = ps.body_point.data();
    a.role = ps[role_].data();
    a.number_density = ps[number_density_].data();
    a.surface = ps[surface_].data();
    a.active = active_.data();
    a.scratch = velocity_scratch_.data();
    return a;
  }

  // u* = u + dt (g + nu lap u), x* = x + dt u*. Walls and bodies are no-slip: their own
  // velocities enter the viscous Laplacian. Then the collisions.
  void predict(Real dt) {
    const auto& s = this->state();
    // The explicit variant's pressure waves need damping: an artificial viscosity
    // alpha c0 l0 on top of the fluid's own.
    const Real nu = s.kinematic_viscosity +
                    (explicit_variant() ? p_.artificial_viscosity * p_.sound_speed * s.spacing : 0);
    if (device_) return this->on_device([&] { device_->predict(dt, nu); });
    const MpsArrays<D> a = arrays();
    const std::size_t n = s.particles.size();
    exec::Default::for_each_balanced(n, MpsPrediction<D>{a, operators(), s.gravity, nu, dt});
    exec::Default::for_each(n, MpsTakeVelocity<D>{a, dt});
    collide(dt);
  }

  // The collisions of mps_loop_bodies.hpp, within collision_distance l0.
  void collide(Real dt) {
    if (p_.collision_distance <= 0) return;
    const Real reach = p_.collision_distance * this->state().spacing;
    const MpsArrays<D> a = arrays();
    const std::size_t n = this->state().particles.size();
    exec::Default::for_each_balanced(
        n, MpsCollision<D>{a, neighbours_.view(), reach * reach, p_.collision_restitution});
    exec::Default::for_each(n, MpsAddVelocity<D>{a, dt});
  }

  // Number density n*, and the free surface: n* < beta n0, confirmed by fewer neighbours than
  // surface_count_ratio of a full lattice's (Tanaka & Masunaga 2010), so that an inner particle
  // whose density dips is not taken for a surface one. Wall particles that no fluid particle
  // reaches are inactive: no pressure, and out of the fluid's operators.
  void find_surface() {
    if (device_) return this->on_device([&] { device_->find_surface(); });
    const MpsArrays<D> a = arrays();
    exec::Default::for_each_balanced(
        this->state().particles.size(),
        MpsNumberDensity<D>{a, operators(), p_.surface_threshold * lattice_.n0,
                            p_.surface_count_ratio * lattice_.neighbours, extrapolated_walls()});
  }

  PressureEquationInputs<D> inputs(Real dt) {
    const auto& s = this->state();
    const auto& ps = s.particles;
    if (extrapolated_walls()) {
      // Each wall and body particle: whether the fluid reaches it, g - a_w, and its velocity
      // carried on by dt (g - a_w) for the fluid's divergence (pressure_equation.hpp).
      extrapolated_.resize(ps.size());
      wall_gravity_.resize(ps.size());
      source_velocity_.resize(ps.size());
      const auto& acceleration = s.body_point_acceleration;
      exec::Default::for_each(
          ps.size(),
          MpsWallInputs<D>{arrays(), acceleration.empty() ? nullptr : acceleration.front().data(),
                           s.gravity, dt, extrapolated_.data(), wall_gravity_.data(),
                           source_velocity_.data()});
    }
    const MpsArrays<D> a = arrays();
    PressureEquationInputs<D> in{
        operators(),      ps.size(), extrapolated_walls() ? source_velocity_.data() : a.velocity,
        a.number_density, a.surface, a.active,
        a.pressure};
    in.dt = dt;
    in.density = density_;
    in.relaxation = p_.source_relaxation;
    in.compressibility = p_.compressibility;
    in.pressure_memory = p_.pressure_memory;
    if (extrapolated_walls()) {
      in.extrapolated = extrapolated_.data();
      in.wall_gravity = wall_gravity_.data();
    }
    return in;
  }

  void assemble(Real dt) {
    if (device_) {
      return this->on_device([&] {
        device_->assemble(dt, p_.source_relaxation, p_.compressibility, p_.pressure_memory);
      });
    }
    const PressureEquationInputs<D> in = inputs(dt);
    equation_.number_unknowns(in, this->counted_kinds());
    this->refresh_ghosts(equation_.row_numbers());  // split: a ghost's row is its owner's
    equation_.assemble_numbered(in);
  }

  void solve(const StepClock& clock) {
    bool solved = false;
    if (device_) {
      this->on_device([&] { solved = device_->solve(); });
    } else {
      solved = equation_.solve(this->state().particles.pressure);
      this->refresh_ghosts(this->state().particles.pressure);  // split: the owners solved them
      prescribe_outlets();
    }
    const PressureEquationReport& r = last_solve();
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

  // Explicit variant: the equation of state (mps_loop_bodies.hpp).
  void pressure_from_density() {
    const Real stiffness = p_.sound_speed * p_.sound_speed * density_ / lattice_.n0;
    if (device_) {
      this->on_device([&] { device_->state_equation(stiffness); });
    } else {
      exec::Default::for_each(this->state().particles.size(),
                              MpsStateEquation<D>{arrays(), stiffness, lattice_.n0});
      this->refresh_ghosts(this->state().particles.pressure);  // split: as the owners have it
      prescribe_outlets();
    }
    clamp_negative();
  }

  // An outlet's pressure, where it prescribes one. Its free surface's pressure vanishes at the
  // surface particles' centres, dx/2 below the water's surface: so does an outlet's hydrostatic
  // pressure.
  void prescribe_outlets() {
    this->prescribe_outlet_pressure([&](Real) { return density_; }, -0.5 * this->state().spacing);
  }

  void clamp_negative() {
    if (p_.keep_negative_pressure) return;
    if (device_) return this->on_device([&] { device_->clamp_negative(); });
    exec::Default::for_each(this->state().particles.size(), MpsClampPressure<D>{arrays()});
  }

  // u = u* - dt / rho grad p, x = x* + dt (u - u*).
  void correct(Real dt) {
    if (device_) return this->on_device([&] { device_->correct(dt); });
    const MpsArrays<D> a = arrays();
    const std::size_t n = this->state().particles.size();
    exec::Default::for_each_balanced(n, MpsPressureCorrection<D>{a, operators(), dt / density_,
                                                                 p_.minimum_density * lattice_.n0});
    exec::Default::for_each(n, MpsAddVelocity<D>{a, dt});
    // Split, the next prediction reads the ghosts' velocities and places as their owners moved
    // them.
    auto& ps = this->state().particles;
    this->refresh_ghosts(ps.position, ps.velocity);
  }

  void measure_extremes() {
    if (device_) {
      max_speed_ = device_->max_speed();
      return;
    }
    const MpsArrays<D> a = arrays();
    max_speed_ = exec::Default::max_of(this->state().particles.size(),
                                       FluidVectorNorm<D>{this->counted_kinds(), a.velocity});
  }

  // The device run (model.device: emulated), from the host's particles as initialize() left
  // them; the base owns it and runs its own services there, the model its stages.
  void start_device() {
    const auto& s = this->state();
    MpsDeviceSetup<D> setup;
    setup.base = this->device_setup();
    setup.weight = weight_;
    setup.laplacian_weight = laplacian_weight_;
    setup.lattice = lattice_;
    setup.laplacian_lattice = laplacian_lattice_;
    setup.gradient_correction = p_.gradient_correction;
    setup.neighbour_radius = s.cells.radius();
    setup.extrapolated_walls = extrapolated_walls();
    setup.collision_reach = p_.collision_distance * s.spacing;
    setup.collision_restitution = p_.collision_restitution;
    setup.gravity = s.gravity;
    setup.density = density_;
    setup.surface_density = p_.surface_threshold * lattice_.n0;
    setup.surface_count = p_.surface_count_ratio * lattice_.neighbours;
    setup.minimum_density = p_.minimum_density * lattice_.n0;
    setup.solver = p_.solver;
    setup.solver_settings = p_.solver_settings;
    std::unique_ptr<MpsDeviceRun<D>> run = make_mps_emulated_run<D>(setup);
    device_ = run.get();
    this->run_on_device(std::move(run));
    // The list the host built; the activity from it, on the device, as the host found it.
    this->on_device([&] {
      device_->upload_neighbours(neighbours_.starts(), neighbours_.indices());
      device_->find_surface();
    });
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
  MpsDeviceRun<D>* device_ = nullptr;  // with model.device: emulated (the base owns it)
};

}  // namespace sluice
