// Weakly compressible SPH (seed 001, method 1; Monaghan 1992): continuity density with
// density diffusion, Tait equation of state, artificial and laminar viscosity, kick-drift-kick
// leapfrog. Walls are boundary particles whose pressure, density and velocity are
// extrapolated from the fluid (Adami, Hu & Adams 2012), so the fluid sees them through the
// ordinary momentum equation, with no gap at the wall. With `model.background_pressure` the
// particles drift with a transport velocity (transport_velocity.hpp). The step's loop bodies
// (wcsph_loop_bodies.hpp) run on the host's particle set with the OpenMP policy, or, with
// `model.device`, on a device's copy of it (wcsph_device_run.hpp).
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

#include "sluice/exec/policy.hpp"
#include "sluice/fluid/particle_fluid.hpp"
#include "sluice/fluid/wcsph/packed_particles.hpp"
#include "sluice/fluid/wcsph/tait.hpp"
#include "sluice/fluid/wcsph/transport_velocity.hpp"
#include "sluice/fluid/wcsph/wcsph_boundaries.hpp"
#include "sluice/fluid/wcsph/wcsph_device_run.hpp"
#include "sluice/fluid/wcsph/wcsph_loop_bodies.hpp"
#include "sluice/fluid/wcsph/wcsph_parameters.hpp"

namespace sluice {

template <int D, class Kernel>
class WcsphModel final : public ParticleFluid<D> {
  using Base = ParticleFluid<D>;

 public:
  WcsphModel(const WcsphParameters& parameters, const io::CaseConfig& config,
             const BodyGeometry& bodies)
      : ParticleFluid<D>(config, Kernel(parameters.smoothing_length(config.spacing)).support(),
                         bodies),
        bodies_(bodies),
        p_(parameters),
        kernel_(parameters.smoothing_length(config.spacing)),
        eos_(config.fluid.density, parameters.sound_speed, parameters.gamma,
             parameters.clamp_negative_pressure),
        boundary_(wcsph_boundaries<D, Kernel>().make(parameters.boundary)) {}

  std::string describe() const override {
    std::string out = fmt::format(
        "wcsph: kernel {}, h = {:.4g} m ({} dx), c0 = {:.4g} m/s, alpha = {}, delta = {}, "
        "walls {}, negative pressure {}",
        Kernel::kName, kernel_.h, p_.h_over_dx, eos_.c0, p_.artificial_viscosity,
        p_.density_diffusion, p_.no_slip ? "no-slip" : "free-slip",
        p_.clamp_negative_pressure ? "clamped" : "kept");
    if (p_.background_pressure > 0)
      out += fmt::format(", transport velocity (p_b = {:.4g} Pa)", p_.background_pressure);
    if (device_) {
      out += fmt::format(", on {} ({:.0f} bytes per particle there)", device_->name(),
                         device_->bytes_per_particle());
    }
    return out;
  }

  void initialize() override {
    ParticleState<D>& s = this->state();
    auto& ps = s.particles;
    fields_ = add_wcsph_fields(ps);
    if (p_.background_pressure > 0)
      background_ = ps.add_vector_field({"background_acceleration", "m/s^2"});
    this->carry_through_put_back(fields_.half_velocity);
    // The builder set a hydrostatic pressure; the density follows from the equation of state.
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (ps.is_fluid(i)) ps.density[i] = eos_.density(ps.pressure[i]);
    }
    update_walls(s);
    compute_rates(s);
    measure_extremes(s);
    if (p_.device != WcsphDevice::kCpu) start_device();
  }

  void archive_model(StateArchive& a) override { a(max_speed_, max_acceleration_); }
  void gather_model(StateArchive& a, bool first) override {
    Real speed = 0, acceleration = 0;
    a(speed, acceleration);
    max_speed_ = first ? speed : std::max(max_speed_, speed);
    max_acceleration_ = first ? acceleration : std::max(max_acceleration_, acceleration);
  }

  void archive_state(StateArchive& a) override {
    Base::archive_state(a);  // on a device, uploads what it read
    // The bodies were read before the fluid (Simulation::archive_state): the device places
    // their points where they stand.
    if (a.reading() && device_) place_body_points_on_device();
  }

  void model_stages(StageList& before, StageList& after) override {
    before.push_back(make_stage<const StepClock>("kick_drift", [this](const StepClock& c) {
      if (device_) return this->on_device([&] { device_->kick_drift(c.dt); });
      kick_drift(this->state(), c.dt);
    }));
    after.push_back(make_stage<const StepClock>("wall_state", [this](const StepClock&) {
      if (device_) return this->on_device([&] { device_->update_walls(); });
      update_walls(this->state());
    }));
    after.push_back(make_stage<const StepClock>("forces", [this](const StepClock&) {
      if (device_) return this->on_device([&] { device_->compute_rates(); });
      compute_rates(this->state());
    }));
    after.push_back(make_stage<const StepClock>("kick", [this](const StepClock& c) {
      if (device_) {
        return this->on_device([&] {
          device_->kick(c.dt);
          const auto e = device_->extremes();
          max_speed_ = e.max_speed;
          max_acceleration_ = e.max_acceleration;
        });
      }
      kick(this->state(), c.dt);
      measure_extremes(this->state());
    }));
  }

  // On a device, the loads are summed there from the points where the last motion put them:
  // one transfer of 6 reals per body.
  std::vector<Wrench> body_loads(const std::vector<BodyKinematics>& motion) const override {
    if (!device_) return Base::body_loads(motion);
    std::vector<Vec3> centre(motion.size());
    for (std::size_t b = 0; b < motion.size(); ++b) centre[b] = motion[b].position;
    std::vector<Wrench> out;
    device_->body_loads(centre, out);
    return out;
  }

  // The model's own fields, for tests that check the pair loops against a reference.
  FieldHandle<Vec<D>> acceleration_field() const { return fields_.acceleration; }
  FieldHandle<Real> density_rate_field() const { return fields_.density_rate; }
  FieldHandle<Vec<D>> wall_velocity_field() const { return fields_.wall_velocity; }

  TimeStep next_time_step() const override {
    const ParticleState<D>& s = this->state();
    const Real h = kernel_.h;
    TimeStep step;
    step.tighten(p_.cfl * h / (eos_.c0 + max_speed_), "the speed of sound and the flow speed");
    if (max_acceleration_ > 0)
      step.tighten(p_.force_cfl * std::sqrt(h / max_acceleration_), "the largest acceleration");
    if (s.kinematic_viscosity > 0)
      step.tighten(0.125 * h * h / s.kinematic_viscosity, "the viscosity");
    return step;
  }

 protected:
  // An open boundary's particles that became fluid start their step from where they stand:
  // half-step values as the present ones, no rates yet.
  void handed_over(const BufferHandOver& hand_over) override {
    auto& ps = this->state().particles;
    for (const std::uint32_t i : hand_over.joined) {
      ps[fields_.half_velocity][i] = ps.velocity[i];
      ps[fields_.half_density][i] = ps.density[i];
      ps[fields_.acceleration][i] = Vec<D>::Zero();
      ps[fields_.density_rate][i] = 0;
      if (background_) ps[*background_][i] = Vec<D>::Zero();
    }
  }

  // The fluid's force on each body particle w: minus the force that w exerts on its fluid
  // neighbours i, from the very pair term that gives the fluid's acceleration (in double).
  void body_point_forces(const std::vector<BodyKinematics>&,
                         std::vector<Vec3>& force) const override {
    const ParticleState<D>& s = this->state();
    exec::Default::for_each_balanced(
        s.particles.size(), WcsphBodyPointForce<D, Kernel>{
                                neighbourhood(s), force.empty() ? nullptr : force.front().data()});
  }

 private:
  // The device's run, from the host's particles as initialize() left them; the base owns it
  // and runs its own services there, the model its stages.
  void start_device() {
    const ParticleState<D>& s = this->state();
    WcsphDeviceSetup<D, Kernel> setup{constants(s), this->device_setup()};
    std::unique_ptr<WcsphDeviceRun<D>> run = make_wcsph_device_run<D, Kernel>(p_.device, setup);
    run->time_stages = p_.time_device_stages;
    device_ = run.get();
    this->run_on_device(std::move(run));
    place_body_points_on_device();
  }

  // The device places the body points from the bodies' motion (the base sends it 19 reals a
  // body at each exchange): at the start, and on a resume, where the bodies stand then.
  void place_body_points_on_device() {
    this->on_device([&] { device_->set_body_motion(pack_body_motion(bodies_.motion())); });
  }

  // The host's particle set as the loop bodies see it.
  WcsphFields<D> fields(const ParticleState<D>& s) const {
    static_assert(sizeof(Vec<D>) == D * sizeof(Real), "a vector is D reals in a row");
    auto& ps = const_cast<ParticleSet<D>&>(s.particles);
    const auto& a = s.body_point_acceleration;
    return wcsph_fields<D>(ps, a.empty() ? nullptr : a.front().data());
  }

  // What the neighbour loops read, the packed copy as the last pack left it.
  WcsphNeighbourhood<D, Kernel> neighbourhood(const ParticleState<D>& s) const {
    return {fields(s), packed_.view(), s.cells.view(), constants(s)};
  }

  WcsphConstants<D, Kernel> constants(const ParticleState<D>& s) const {
    WcsphConstants<D, Kernel> c{kernel_, eos_, pair_constants(s)};
    const Vec3 g = to_3d<D>(s.gravity);
    for (int a = 0; a < 3; ++a) c.gravity[a] = g[a];
    c.two_nu_rho0 = 2 * s.kinematic_viscosity * eos_.rho0;
    c.no_slip = p_.no_slip;
    return c;
  }

  // First half kick and drift; velocity and density are then predicted to the end of the
  // step for the force evaluation, which keeps one force evaluation per step.
  void kick_drift(ParticleState<D>& s, Real dt) {
    exec::Default::for_each(s.particles.size(),
                            WcsphKickDrift<D>{fields(s), dt, eos_, background_acceleration(s)});
  }

  Real* background_acceleration(ParticleState<D>& s) const {
    return background_ ? s.particles.template components<Real>("background_acceleration") : nullptr;
  }

  void kick(ParticleState<D>& s, Real dt) {
    exec::Default::for_each(s.particles.size(), WcsphKick<D>{fields(s), dt, eos_});
  }

  void measure_extremes(const ParticleState<D>& s) {
    WcsphFields<D> f = fields(s);
    f.kind = this->counted_kinds();  // a ghost's rates are its owner's to count
    max_speed_ = exec::Default::max_of(s.particles.size(), FluidMagnitude<D>{f, f.velocity});
    max_acceleration_ =
        exec::Default::max_of(s.particles.size(), FluidMagnitude<D>{f, f.acceleration});
  }

  // Copies what the pair loops read into the packed single-precision arrays.
  void pack(const ParticleState<D>& s, bool with_rates) {
    const auto& ps = s.particles;
    packed_.fluid_before.resize(ps.size() + 1);
    packed_.fluid_before[0] = 0;
    for (std::size_t j = 0; j < ps.size(); ++j) {
      packed_.fluid_before[j + 1] = packed_.fluid_before[j] + (ps.is_fluid(j) ? 1 : 0);
    }
    packed_.resize(ps.size(), packed_.fluid_before.back());
    exec::Default::for_each(ps.size(),
                            WcsphPack<D>{fields(s), packed_.arrays(), p_.no_slip, with_rates});
  }

  // The walls' pressure, density and viscous velocity from the fluid around them, as the
  // boundary treatment sets them.
  void update_walls(ParticleState<D>& s) {
    pack(s, false);
    WcsphBoundaryContext<D, Kernel> context = neighbourhood(s);
    boundary_->update(context);
    this->prescribe_outlet_pressure([&](Real p) { return eos_.density(p); });
  }

  // Continuity with density diffusion and the momentum equation, gathered per fluid particle
  // (each pair evaluated from both sides, so no two threads write the same particle).
  void compute_rates(ParticleState<D>& s) {
    pack(s, true);
    WcsphNeighbourhood<D, Kernel> n = neighbourhood(s);
    // A ghost's rates are its owner's to work out (its neighbours are read from the packed copy,
    // which keeps every kind): split, a ghost counts as no fluid here.
    n.f.kind = this->counted_kinds();
    exec::Default::for_each_balanced(s.particles.size(), WcsphRates<D, Kernel>{n});
    if (background_) {
      exec::Default::for_each_balanced(
          s.particles.size(), WcsphBackgroundAcceleration<D, Kernel>{n, p_.background_pressure,
                                                                     background_acceleration(s)});
    }
  }

  WcsphPairConstants pair_constants(const ParticleState<D>& s) const {
    const Real h = kernel_.h;
    const Real c0 = eos_.c0;
    WcsphPairConstants k;
    k.eta2 = static_cast<float>(0.01 * h * h);
    k.two_alpha_c0_h = static_cast<float>(2 * p_.artificial_viscosity * c0 * h);
    // Molteni & Colagrossi (2009) diffusion, with the hydrostatic part of the density
    // difference removed (Fourtakas et al. 2019), linearised: rho_H_ji = rho0 g.r_ji / c0^2.
    k.diffusion = static_cast<float>(-2 * p_.density_diffusion * h * c0);
    const Vec3 g = to_3d<D>(s.gravity);
    for (int a = 0; a < 3; ++a)
      k.hydrostatic[a] = static_cast<float>(-(eos_.rho0 / (c0 * c0)) * g[a]);
    return k;
  }

  const BodyGeometry& bodies_;
  WcsphParameters p_;
  Kernel kernel_;
  TaitEquation eos_;
  WcsphFieldHandles<D> fields_;
  // With a transport velocity: the background pressure's acceleration of each fluid particle.
  std::optional<FieldHandle<Vec<D>>> background_;
  std::unique_ptr<BoundaryTreatment<WcsphBoundaryContext<D, Kernel>>> boundary_;
  PackedParticles packed_;
  Real max_speed_ = 0;
  Real max_acceleration_ = 0;
  // With model.device: the run there (the base owns it).
  WcsphDeviceRun<D>* device_ = nullptr;
};

}  // namespace sluice
