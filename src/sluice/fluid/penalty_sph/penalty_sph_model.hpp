// Müller-style SPH with penalty boundaries (seed 002; Müller, Charypar & Gross 2003): density
// by summation with the poly6 kernel, pressure p = k (rho - rho0), the symmetric pressure force
// with the spiky kernel's gradient (consistent, or Müller et al.'s half), Monaghan's artificial
// viscosity (Monaghan 1992), viscosity through the viscosity kernel's Laplacian, gravity,
// buoyancy b (rho - rho0) g and surface tension from the colour field. The walls, the bodies
// and the case's solid layers (`model.solids`, each on a lattice of its own spacing L_b) are
// solid particles that push the fluid out with the penalty law of penalty_boundary.hpp and
// drag it with the no-slip traction; a fluid particle meets them in sub-steps of its own with
// its fluid force held (solid_contact_stepper.hpp). Kick-drift-kick leap-frog around that.
// Fluid forces are densities (N/m^3), as in Müller et al.; the boundary force is a force (N).
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include "sluice/core/errors.hpp"
#include "sluice/exec/policy.hpp"
#include "sluice/fluid/fluid_vector_norm.hpp"
#include "sluice/fluid/particle_fluid.hpp"
#include "sluice/fluid/penalty_sph/lattice_sums.hpp"
#include "sluice/fluid/penalty_sph/layer_passage.hpp"
#include "sluice/fluid/penalty_sph/penalty_drift.hpp"
#include "sluice/fluid/penalty_sph/penalty_sph_device_run.hpp"
#include "sluice/fluid/penalty_sph/penalty_sph_loop_bodies.hpp"
#include "sluice/fluid/penalty_sph/penalty_sph_parameters.hpp"
#include "sluice/fluid/penalty_sph/solid_contact_stepper.hpp"
#include "sluice/fluid/penalty_sph/solid_layers.hpp"
#include "sluice/fluid/penalty_sph/stiffness_suggestion.hpp"
#include "sluice/geometry/sampling.hpp"

namespace sluice {

template <int D>
class PenaltySphModel final : public ParticleFluid<D> {
 public:
  PenaltySphModel(const PenaltySphParameters& parameters, const io::CaseConfig& config,
                  const BodyGeometry& bodies)
      : ParticleFluid<D>(config, parameters.smoothing_length(config.spacing, D), bodies),
        p_(parameters),
        config_(config),
        kernels_(parameters.smoothing_length(config.spacing, D)),
        rest_density_(config.fluid.density),
        viscosity_(config.fluid.density * config.fluid.kinematic_viscosity),
        particle_mass_(config.fluid.density * std::pow(config.spacing, D)),
        lattice_correction_(rest_density_ /
                            (particle_mass_ * lattice_poly6_sum(kernels_, config.spacing))),
        pressure_weight_(parameters.muller_pressure_force ? 0.5 : 1.0),
        gradient_gain_(lattice_gradient_gain(kernels_, config.spacing)),
        damping_(parameters.artificial_viscosity * std::sqrt(parameters.gas_stiffness) *
                 parameters.smoothing_length(config.spacing, D)) {
    settings_.law.stiffness =
        p_.stiffness > 0 ? p_.stiffness
                         : energy_rule_stiffness(particle_mass_, p_.max_speed, config.spacing);
    // Without a given Kd, critical damping of one contact: water does not bounce off a wall.
    settings_.law.damping =
        p_.damping > 0 ? p_.damping : 2 * std::sqrt(settings_.law.stiffness * particle_mass_);
    settings_.wall_friction = p_.wall_friction;
    settings_.kernels = kernels_;
  }

  std::string describe() const override {
    std::string out = fmt::format(
        "penalty-sph: h = {:.4g} m ({} particles in the support), k = {:.4g} m^2/s^2 ({} pressure "
        "force), artificial viscosity {}, b = {}, sigma = {} N/m",
        kernels_.h, p_.kernel_particles, p_.gas_stiffness,
        p_.muller_pressure_force ? "Mueller's half" : "consistent", p_.artificial_viscosity,
        p_.buoyancy, p_.surface_tension);
    out += fmt::format(", Ks = {:.4g} N/m, Kd = {:.4g} N s/m, wall friction {:.4g} Pa s",
                       settings_.law.stiffness, settings_.law.damping, p_.wall_friction);
    out += fmt::format(", {} solid layer(s)", p_.solids.size());
    if (p_.time_step > 0) out += fmt::format(", fixed dt = {} s", p_.time_step);
    if (device_) {
      out += fmt::format(", on {} ({:.0f} bytes per particle there)", device_->name(),
                         device_->bytes_per_particle());
    }
    return out + layer_stiffness_advice<D>(p_, config_, particle_mass_);
  }

  void initialize() override {
    auto& ps = this->state().particles;
    acceleration_ = ps.add_vector_field({"acceleration", "m/s^2"});
    half_velocity_ = ps.add_vector_field({"half_step_velocity", "m/s"});
    this->carry_through_put_back(half_velocity_);
    boundary_force_ = ps.add_vector_field({"boundary_force", "N", true});
    solid_spacing_ = ps.add_scalar_field({"solid_spacing", "m", true});
    passage_.add_fields(ps);
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (!ps.is_fluid(i)) ps[solid_spacing_][i] = config_.spacing;
      // A grain of a free layer is one solid particle as wide as the grain.
      if (const io::BodyConfig* grain = grain_of(i)) ps[solid_spacing_][i] = 2 * grain->radius;
    }
    if (!p_.solids.empty()) {
      std::vector<GrainBodies> grain_bodies =
          add_solid_layers(p_.solids, config_, ps, solid_spacing_);
      sort_again();
      passage_.start(ps, p_.solids, std::move(grain_bodies));
    }
    has_bodies_ = this->body_points().size() > 0;
    contact_support_ = contact_support();
    // Split once the solid layers stand, before the first rates, which each rank then works out
    // over its own particles and its ghosts (a periodic side's images too).
    this->distribute(split_.value_or(Communicator::alone()), halo_depth());
    compute_density();
    compute_forces();
    measure_extremes();
    if (p_.emulated_device) start_device();
  }

  TimeStep next_time_step() const override {
    TimeStep step;
    if (p_.time_step > 0) {
      step.tighten(p_.time_step, "model.time_step");
      return step;
    }
    const Real h = kernels_.h;
    const Real c0 = std::sqrt(p_.gas_stiffness);
    step.tighten(p_.cfl * h / (c0 + max_speed_), "the speed of sound and the flow speed");
    if (max_acceleration_ > 0)
      step.tighten(p_.cfl * std::sqrt(h / max_acceleration_), "the largest acceleration");
    const Real nu = viscosity_ / rest_density_;
    if (nu > 0) step.tighten(0.125 * h * h / nu, "the viscosity");
    // Capillary waves (Brackbill, Kothe & Zemach 1992): dt < sqrt(rho h^3 / (2 pi sigma)).
    if (p_.surface_tension > 0) {
      step.tighten(
          std::sqrt(rest_density_ * h * h * h / (2 * std::numbers::pi * p_.surface_tension)),
          "the surface tension");
    }
    return step;
  }

  std::vector<std::pair<std::string, double>> counters() const override {
    // Over the ranks: each counts its own particles' contacts (fluid_steps_ counts the whole
    // case's fluid on every rank).
    const Communicator& ranks = this->ranks();
    std::array<double, 4> sums{double(contacts_), force_sum_, double(crossings_),
                               double(substeps_)};
    ranks.sum(sums);
    const auto [contacts, force_sum, crossings, substeps] = sums;
    const double particle_steps = static_cast<double>(fluid_steps_);
    std::vector<std::pair<std::string, double>> out = {
        {"boundary_contacts_per_step", steps_ > 0 ? contacts / double(steps_) : 0},
        {"mean_boundary_force", contacts > 0 ? force_sum / contacts : 0},
        {"peak_boundary_force", ranks.max(peak_force_)},
        {"boundary_crossings", crossings},
        {"contact_substeps_per_particle_step", particle_steps > 0 ? substeps / particle_steps : 0}};
    if (passage_.measured()) {
      out.emplace_back(
          "held_back_fraction",
          passage_.held_back_fraction(this->state().particles, this->counted_kinds(), ranks));
    }
    for (auto& entry : ParticleFluid<D>::counters()) out.push_back(std::move(entry));
    return out;
  }

  FluidEnergy energy() const override {
    FluidEnergy e = ParticleFluid<D>::energy();
    e.elastic = elastic_energy();
    return e;
  }

  // From initialize() on, the particles split over `ranks` (ParticleFluid::distribute).
  void split_over(const Communicator& ranks) { split_ = ranks; }

  const PenaltyLaw& law() const { return settings_.law; }
  FieldHandle<Vec<D>> boundary_force_field() const { return boundary_force_; }

 protected:
  // The walls and fixed layers are gathered at the first step and never move: read back, they
  // are gathered again at the next.
  void archive_model(StateArchive& a) override {
    // The bodies' start positions and impulses are not kept: the next step's drift and its
    // first exchange rewrite them before anything reads them.
    a(max_speed_, max_acceleration_, body_pressure_force_);
    a(steps_, fluid_steps_, contacts_, crossings_, substeps_, force_sum_, peak_force_);
    if (a.reading()) solids_gathered_ = false;  // gathered again at the next step
  }
  // The ranks' counts and their shares of the bodies' pressure forces add up over the ranks:
  // the first rank holds the pieces' sums.
  void gather_model(StateArchive& a, bool first) override {
    Real speed = 0, acceleration = 0;
    std::vector<Vec<D>> pressure_force;
    long contacts = 0, crossings = 0, substeps = 0;
    double force_sum = 0, peak_force = 0;
    a(speed, acceleration, pressure_force);
    a(steps_, fluid_steps_, contacts, crossings, substeps, force_sum, peak_force);
    if (first) {
      body_pressure_force_.assign(pressure_force.size(), Vec<D>::Zero());
      contacts_ = crossings_ = substeps_ = 0;
      force_sum_ = 0;
    }
    max_speed_ = first ? speed : std::max(max_speed_, speed);
    max_acceleration_ = first ? acceleration : std::max(max_acceleration_, acceleration);
    peak_force_ = first ? peak_force : std::max(peak_force_, peak_force);
    if (this->ranks().rank() == 0) {
      for (std::size_t k = 0; k < pressure_force.size(); ++k)
        body_pressure_force_[k] += pressure_force[k];
      contacts_ += contacts;
      crossings_ += crossings;
      substeps_ += substeps;
      force_sum_ += force_sum;
    }
    solids_gathered_ = false;
  }

  void model_stages(StageList& before, StageList& after) override {
    before.push_back(make_stage<const StepClock>("kick_drift",
                                                 [this](const StepClock& c) { kick_drift(c.dt); }));
    after.push_back(
        make_stage<const StepClock>("density", [this](const StepClock&) { compute_density(); }));
    after.push_back(
        make_stage<const StepClock>("forces", [this](const StepClock&) { compute_forces(); }));
    after.push_back(make_stage<const StepClock>("kick", [this](const StepClock& c) {
      kick(c.dt);
      measure_extremes();
    }));
  }

  // The reaction of the boundary forces the fluid felt from each body particle: the penalty
  // and no-slip forces of the last drift, as a mean force over it, and the pressure the body
  // particle holds for its fluid neighbours (as of the last force evaluation).
  void body_point_forces(const std::vector<BodyKinematics>&,
                         std::vector<Vec3>& force) const override {
    for (std::size_t k = 0; k < body_impulse_.size(); ++k) {
      force[k] += to_3d<D>(body_impulse_[k] / last_dt_);
    }
    for (std::size_t k = 0; k < body_pressure_force_.size(); ++k) {
      force[k] += to_3d<D>(body_pressure_force_[k]);
    }
  }

 private:
  // The host's particle set as the loop bodies see it (penalty_sph_loop_bodies.hpp).
  PenaltySphArrays<D> arrays() {
    ParticleState<D>& s = this->state();
    auto& ps = s.particles;
    PenaltySphArrays<D> a;
    a.position = ps.position.data();
    a.velocity = ps.velocity.data();
    a.density = ps.density.data();
    a.pressure = ps.pressure.data();
    a.mass = ps.mass.data();
    a.kind = reinterpret_cast<const std::int32_t*>(ps.kind.data());
    a.body_point = ps.body_point.data();
    a.solid_spacing = ps[solid_spacing_].data();
    a.acceleration = ps[acceleration_].data();
    a.half_velocity = ps[half_velocity_].data();
    const auto& acceleration = s.body_point_acceleration;
    a.point_acceleration = acceleration.empty() ? nullptr : acceleration.front().data();
    return a;
  }
  PenaltyDriftArrays<D> drift_arrays() {
    auto& ps = this->state().particles;
    return {ps.position.data(), ps[half_velocity_].data(), ps.mass.data(), ps.density.data(),
            step_results_.data()};
  }
  Vec<D>* boundary() { return this->state().particles[boundary_force_].data(); }
  PenaltySphConstants<D> constants() const {
    return {kernels_,
            this->state().gravity,
            rest_density_,
            p_.gas_stiffness,
            p_.keep_negative_pressure,
            lattice_correction_,
            pressure_weight_,
            gradient_gain_,
            damping_,
            viscosity_,
            p_.buoyancy,
            p_.surface_tension,
            p_.surface_threshold};
  }

  // The body of particle i when it is a grain of a free solid layer, else null.
  const io::BodyConfig* grain_of(std::size_t i) const {
    const std::int32_t k = this->state().particles.body_point[i];
    if (k < 0) return nullptr;
    const io::BodyConfig& body = config_.bodies[this->body_points()[std::size_t(k)].body];
    return body.seen_as_one_particle ? &body : nullptr;
  }

  // The device run (model.device: emulated), from the host's particles as initialize() left
  // them; the base owns it and runs its own services there, the model its stages.
  void start_device() {
    const PenaltySphDeviceSetup<D> setup{this->device_setup(), constants(), settings_,
                                         config_.spacing};
    std::unique_ptr<PenaltySphDeviceRun<D>> run = make_penalty_sph_emulated_run<D>(setup);
    device_ = run.get();
    this->run_on_device(std::move(run));
  }

  // The walls and fixed layers this rank holds, into solids_.
  void gather_fixed_solids() {
    auto& ps = this->state().particles;
    solids_.gather(ps, ps[solid_spacing_], config_.spacing, contact_support_);
    solids_gathered_ = true;
    gathered_at_cut_move_ = this->cut_moves();
  }

  // Split, what a rank holds of the walls changes where its cuts move (at the exchange of the
  // neighbour stage): gathered again at once, for the contacts the energy counts and the drift.
  void sort_by_cell() override {
    ParticleFluid<D>::sort_by_cell();
    if (!device_ && solids_gathered_ && gathered_at_cut_move_ != this->cut_moves())
      gather_fixed_solids();
  }

  // The particles sorted by cell again, over a box that holds the solid layers too.
  void sort_again() {
    ParticleState<D>& s = this->state();
    auto& ps = s.particles;
    Vec<D> lo = ps.position.front(), hi = lo;
    for (const Vec<D>& x : ps.position) {
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
    s.cells = CellList<D>(lo, hi, this->interaction_radius());
    std::vector<std::uint32_t> order;
    s.cells.sort(ps.position, order);
    ps.reorder(order);
  }

  // Half kick with the held fluid force, then the drift through the solids (which may stop
  // the particle). With bodies, only the particles that cannot meet one within the step drift
  // now; the rest drift with the bodies, exchange by exchange (advance_with_bodies).
  void kick_drift(Real dt) {
    step_dt_ = dt;
    drifted_ = 0;
    if (device_) {
      this->on_device([&] {
        if (!solids_gathered_) device_->gather_fixed_solids();
        device_->half_kick(dt);
        device_->start_drift(dt, has_bodies_);
      });
      solids_gathered_ = true;
      if (!has_bodies_) finish_drift();
      return;
    }
    auto& ps = this->state().particles;
    // Walls and fixed solid layers stand still: gathered once (again where split cuts move).
    if (!solids_gathered_) gather_fixed_solids();
    // Split, a rank drifts its own fluid particles; its ghosts are taken anew after the drift.
    const std::int32_t* kinds = this->counted_kinds();
    step_results_.assign(ps.size(), {});
    exec::Default::for_each(ps.size(), PenaltyHalfKick<D>{arrays(), dt});
    if (!has_bodies_) {
      drifting_.clear();
      for (std::size_t i = 0; i < ps.size(); ++i) {
        if (kinds[i] == 0) drifting_.push_back(static_cast<std::uint32_t>(i));
      }
      drift(drifting_, dt, false);
      finish_drift();
      return;
    }
    // The bodies' particles where they stand, and the fluid particles out of their reach
    // over the whole step (however fast either moves) drift at once.
    body_particles_.clear();
    Vec<D> lo = Vec<D>::Constant(std::numeric_limits<Real>::max()), hi = -lo;
    Real body_speed = 0;
    body_start_.resize(this->body_points().size());
    for (std::size_t i = 0; i < ps.size(); ++i) {
      const std::int32_t point = ps.body_point[i];
      if (point < 0) continue;
      body_particles_.push_back(static_cast<std::uint32_t>(i));
      body_start_[std::size_t(point)] = ps.position[i];
      lo = lo.cwiseMin(ps.position[i]);
      hi = hi.cwiseMax(ps.position[i]);
      body_speed = std::max(body_speed, ps.velocity[i].norm());
    }
    solids_.gather_moving(ps, ps[solid_spacing_], body_particles_, body_start_, 0);
    std::vector<std::uint32_t> far;
    drifting_.clear();
    const PenaltyOutOfBodiesReach<D> out_of_reach{ps.position.data(),
                                                  ps[half_velocity_].data(),
                                                  ps[acceleration_].data(),
                                                  lo,
                                                  hi,
                                                  body_speed,
                                                  solids_.support,
                                                  dt};
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (kinds[i] == 0) (out_of_reach(i) ? far : drifting_).push_back(std::uint32_t(i));
    }
    drift(far, dt, false);
  }

  // One exchange with the bodies: they have advanced by dt and the fluid's body particles
  // stand where they now are; the fluid particles in their reach drift by dt against them.
  void advance_with_bodies(double dt) override {
    if (device_) {
      this->on_device([&] { device_->drift_with_bodies(dt, body_impulse_); });
      last_dt_ = dt;
    } else {
      auto& ps = this->state().particles;
      solids_.gather_moving(ps, ps[solid_spacing_], body_particles_, body_start_, dt);
      drift(drifting_, dt, true);
    }
    drifted_ += dt;
    if (drifted_ >= step_dt_ * (1 - 1e-9)) finish_drift();
  }

  // The bodies' loads are the model's own sums (body_point_forces): no particle is read. Split,
  // the impulses are what this rank's own fluid put on every point, ghost points too.
  bool body_forces_read_particles() const override { return false; }
  bool body_point_forces_are_rank_shares() const override { return true; }

  // The contact support S: the largest (L_b + l0) / 2 of the case's solids, and not below the
  // viscosity kernel's h (SolidParticles::gather).
  Real contact_support() const {
    const auto& ps = this->state().particles;
    Real support = kernels_.h;
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (!ps.is_fluid(i))
        support = std::max(support, (ps[solid_spacing_][i] + config_.spacing) / 2);
    }
    return support;
  }

  // How deep a rank's ghosts reach beyond its slab: its own fluid particles read the density of
  // every neighbour within h, which that neighbour sums over its own within h (2 h); and a drift
  // meets the solids within two contact supports of where it starts (2 S), bodies' particles
  // that may have moved towards it over the step too (h / 2 more).
  Real halo_depth() const {
    return std::max(2 * kernels_.h, 2 * contact_support_ + kernels_.h / 2);
  }

  // The bodies hang on the fluid by springs of Ks each: the coupler exchanges often enough
  // for the lightest of them.
  double boundary_stiffness() const override { return settings_.law.stiffness; }

  // Drifts the fluid particles `which` by dt through the solids (PenaltyDrift), adding to
  // their step's results; with `on_bodies`, the bodies' share of it becomes their load for the
  // next exchange.
  void drift(const std::vector<std::uint32_t>& which, Real dt, bool on_bodies) {
    if (on_bodies) body_impulses_.resize(which.size());
    exec::Default::for_each_balanced(which.size(), PenaltyDrift<D, HostDriftScratch<D>>{
                                                       drift_arrays(),
                                                       settings_,
                                                       solids_.view(),
                                                       which.data(),
                                                       dt,
                                                       {on_bodies ? &body_impulses_ : nullptr}});
    if (!on_bodies) return;
    // Summed in particle order, so that the loads do not depend on the thread count.
    body_impulse_.assign(this->body_points().size(), Vec<D>::Zero());
    last_dt_ = dt;
    for (std::size_t n = 0; n < which.size(); ++n) {
      for (const BodyImpulse<D>& b : body_impulses_[n]) {
        body_impulse_[static_cast<std::size_t>(b.body_point)] += b.impulse;
      }
    }
  }

  // The step's drift is done: the end-of-step velocity predicted for the viscosity, the
  // boundary force, the counters and which particles passed a layer.
  void finish_drift() {
    if (device_) {
      typename PenaltySphDeviceRun<D>::Totals totals;
      this->on_device([&] { totals = device_->finish_drift(step_dt_); });
      return add_counters(totals);
    }
    auto& ps = this->state().particles;
    const PenaltySphArrays<D> a = arrays();
    exec::Default::for_each(
        ps.size(), PenaltyEndOfDrift<D>{a.kind, a.half_velocity, a.acceleration,
                                        step_results_.data(), a.velocity, boundary(), step_dt_});
    // In index order, as a device's sums take them.
    const auto sum = [&](const auto& value) {
      double total = 0;
      for (std::size_t i = 0; i < ps.size(); ++i) total += value(i);
      return total;
    };
    const auto max = [&](const auto& value) { return exec::Default::max_of(ps.size(), value); };
    add_counters(PenaltyStepCounters<D>{step_results_.data(), boundary()}.totals(sum, max));
    if (!p_.solids.empty()) {
      passage_.update_levels(ps, this->body_points(), this->ranks());
      const std::int32_t* kinds = this->counted_kinds();
      for (std::size_t i = 0; i < ps.size(); ++i) {
        if (kinds[i] == 0) passage_.record(ps, i);
      }
    }
  }
  void add_counters(const typename PenaltyStepCounters<D>::Totals& t) {
    fluid_steps_ += static_cast<long>(this->state().fluid_count);
    substeps_ += static_cast<long>(t.substeps);
    contacts_ += static_cast<long>(t.touched);
    force_sum_ += t.contact_force;
    peak_force_ = std::max(peak_force_, t.peak_force);
    crossings_ += static_cast<long>(t.crossed);
    ++steps_;
  }

  void kick(Real dt) {
    if (device_) return this->on_device([&] { device_->kick(dt); });
    exec::Default::for_each(this->state().particles.size(), PenaltyKick<D>{arrays(), dt});
  }

  // The density by summation and its pressure (PenaltyDensity).
  void compute_density() {
    if (device_) return this->on_device([&] { device_->density(); });
    const ParticleState<D>& s = this->state();
    exec::Default::for_each_balanced(s.particles.size(),
                                     PenaltyDensity<D>{arrays(), constants(), s.cells.view()});
  }

  // The fluid's own force per unit mass, gravity and buoyancy included (PenaltyForces); the
  // solids act in the drift.
  void compute_forces() {
    if (device_) {
      return this->on_device([&] {
        device_->forces();
        if (has_bodies_) device_->body_pressure_forces(body_pressure_force_);
      });
    }
    const ParticleState<D>& s = this->state();
    exec::Default::for_each_balanced(s.particles.size(),
                                     PenaltyForces<D>{arrays(), constants(), s.cells.view()});
    if (has_bodies_) update_body_pressure_forces();
  }

  // Minus the pressure force each body particle exerts on its fluid neighbours
  // (PenaltyBodyPressureForce).
  void update_body_pressure_forces() {
    const ParticleState<D>& s = this->state();
    body_pressure_force_.assign(this->body_points().size(), Vec<D>::Zero());
    exec::Default::for_each(s.particles.size(),
                            PenaltyBodyPressureForce<D>{arrays(), constants(), s.cells.view(),
                                                        body_pressure_force_.data()});
    // Split, a point's owner holds every fluid neighbour of it: a ghost point's force is its
    // owner's to give.
    const std::int32_t* kinds = this->counted_kinds();
    for (std::size_t i = 0; i < s.particles.size(); ++i) {
      const std::int32_t k = s.particles.body_point[i];
      if (k >= 0 && kinds[i] < 0) body_pressure_force_[std::size_t(k)] = Vec<D>::Zero();
    }
  }

  // 1/2 Ks d^2 over the fluid-solid pairs in contact now, summed in index order.
  double elastic_energy() const {
    if (device_) return device_->elastic_energy();
    const auto& ps = this->state().particles;
    const PenaltyElasticEnergy<D> energy{this->counted_kinds(), ps.position.data(), solids_.view(),
                                         settings_.law.stiffness};
    double sum = 0;
    for (std::size_t i = 0; i < ps.size(); ++i) sum += energy(i);
    return this->ranks().sum(sum);
  }

  void measure_extremes() {
    if (device_) {
      max_speed_ = device_->max_speed();
      max_acceleration_ = device_->max_acceleration();
      return;
    }
    const std::size_t n = this->state().particles.size();
    const PenaltySphArrays<D> a = arrays();
    const std::int32_t* kinds = this->counted_kinds();  // a ghost's rates are its owner's
    max_speed_ = exec::Default::max_of(n, FluidVectorNorm<D>{kinds, a.velocity});
    max_acceleration_ = exec::Default::max_of(n, FluidVectorNorm<D>{kinds, a.acceleration});
  }

  PenaltySphParameters p_;
  io::CaseConfig config_;
  MullerKernels<D> kernels_;
  Real rest_density_, viscosity_, particle_mass_;
  // rho0 over the summed density of a full lattice at the spacing: the poly6 sum misses rho0
  // by a few per cent on a lattice, which k = c0^2 would turn into a pressure of its own.
  Real lattice_correction_;
  // The pressure force -sum V_j w (p_i + p_j) grad W: w = 1 estimates grad p; Müller et al.'s
  // w = 1/2 estimates half of it, so that still water holds twice rho g h.
  Real pressure_weight_;
  Real gradient_gain_;  // G of lattice_sums.hpp
  Real damping_;        // alpha c0 h of the artificial viscosity [m^2/s]
  SolidContactSettings<D> settings_;
  SolidParticles<D> solids_;
  FieldHandle<Vec<D>> acceleration_, half_velocity_, boundary_force_;
  FieldHandle<Real> solid_spacing_;
  LayerPassage<D> passage_;
  std::vector<SolidStepResult<D>> step_results_;            // per particle, over the step
  std::vector<std::vector<BodyImpulse<D>>> body_impulses_;  // per drifting particle, scratch
  std::vector<std::uint32_t> drifting_;        // the fluid particles that drift with the bodies
  std::vector<std::uint32_t> body_particles_;  // the bodies' particles, this step
  std::vector<Vec<D>> body_start_;             // per body point: where the last exchange left it
  Real step_dt_ = 0, drifted_ = 0;
  std::vector<Vec<D>> body_impulse_;  // per body point over the last drift [N s], on the body
  std::vector<Vec<D>> body_pressure_force_;  // per body point [N], on the body
  Real last_dt_ = 1;
  bool has_bodies_ = false;
  bool solids_gathered_ = false;       // the walls and fixed layers, in solids_ or on the device
  Real contact_support_ = 0;           // contact_support(), of the whole case
  std::optional<Communicator> split_;  // split_over's ranks
  int gathered_at_cut_move_ = 0;       // cut_moves() when the fixed solids were gathered
  PenaltySphDeviceRun<D>* device_ = nullptr;  // with model.device: emulated (the base owns it)
  Real max_speed_ = 0, max_acceleration_ = 0;
  long steps_ = 0, fluid_steps_ = 0, contacts_ = 0, crossings_ = 0, substeps_ = 0;
  double force_sum_ = 0, peak_force_ = 0;
};

}  // namespace sluice
