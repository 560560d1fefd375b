// Weakly compressible SPH (seed 001, method 1; Monaghan 1992): continuity density with
// density diffusion, Tait equation of state, artificial and laminar viscosity, kick-drift-kick
// leapfrog. Walls are boundary particles whose pressure, density and velocity are
// extrapolated from the fluid (Adami, Hu & Adams 2012), so the fluid sees them through the
// ordinary momentum equation, with no gap at the wall.
#pragma once

#include <fmt/format.h>
#include <algorithm>
#include <cmath>

#include "sluice/exec/policy.hpp"
#include "sluice/fluid/particle_fluid.hpp"
#include "sluice/fluid/wcsph/packed_particles.hpp"
#include "sluice/fluid/wcsph/tait.hpp"
#include "sluice/fluid/wcsph/wcsph_boundaries.hpp"
#include "sluice/fluid/wcsph/wcsph_pair_term.hpp"
#include "sluice/fluid/wcsph/wcsph_parameters.hpp"

namespace sluice {

template <int D, class Kernel>
class WcsphModel final : public ParticleFluid<D> {
 public:
  WcsphModel(const WcsphParameters& parameters, const io::CaseConfig& config,
             const BodyGeometry& bodies)
      : ParticleFluid<D>(config, Kernel(parameters.smoothing_length(config.spacing)).support(),
                         bodies),
        p_(parameters),
        kernel_(parameters.smoothing_length(config.spacing)),
        eos_(config.fluid.density, parameters.sound_speed, parameters.gamma),
        boundary_(wcsph_boundaries<D, Kernel>().make(parameters.boundary)) {}

  std::string describe() const override {
    return fmt::format(
        "wcsph: kernel {}, h = {:.4g} m ({} dx), c0 = {:.4g} m/s, alpha = {}, delta = {}, "
        "walls {}",
        Kernel::kName, kernel_.h, p_.h_over_dx, eos_.c0, p_.artificial_viscosity,
        p_.density_diffusion, p_.no_slip ? "no-slip" : "free-slip");
  }

  void initialize() override {
    ParticleState<D>& s = this->state();
    auto& ps = s.particles;
    acceleration_ = ps.add_vector_field({"acceleration", "m/s^2"});
    density_rate_ = ps.add_scalar_field({"density_rate", "kg/m^3/s"});
    half_velocity_ = ps.add_vector_field({"half_step_velocity", "m/s"});
    half_density_ = ps.add_scalar_field({"half_step_density", "kg/m^3"});
    // Walls: the velocity the viscous terms see (no-slip: mirrored about the wall's own).
    wall_velocity_ = ps.add_vector_field({"wall_velocity", "m/s"});
    // The builder set a hydrostatic pressure; the density follows from the equation of state.
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (ps.is_fluid(i)) ps.density[i] = eos_.density(ps.pressure[i]);
    }
    update_walls(s);
    compute_rates(s);
    measure_extremes(s);
  }

  void archive_model(StateArchive& a) override { a(max_speed_, max_acceleration_); }

  void model_stages(StageList& before, StageList& after) override {
    before.push_back(make_stage<const StepClock>(
        "kick_drift", [this](const StepClock& c) { kick_drift(this->state(), c.dt); }));
    after.push_back(make_stage<const StepClock>(
        "wall_state", [this](const StepClock&) { update_walls(this->state()); }));
    after.push_back(make_stage<const StepClock>(
        "forces", [this](const StepClock&) { compute_rates(this->state()); }));
    after.push_back(make_stage<const StepClock>("kick", [this](const StepClock& c) {
      kick(this->state(), c.dt);
      measure_extremes(this->state());
    }));
  }

  // The model's own fields, for tests that check the pair loops against a reference.
  FieldHandle<Vec<D>> acceleration_field() const { return acceleration_; }
  FieldHandle<Real> density_rate_field() const { return density_rate_; }
  FieldHandle<Vec<D>> wall_velocity_field() const { return wall_velocity_; }

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

 private:
  // First half kick and drift; velocity and density are then predicted to the end of the
  // step for the force evaluation, which keeps one force evaluation per step.
  void kick_drift(ParticleState<D>& s, Real dt) {
    auto& ps = s.particles;
    auto& a = ps[acceleration_];
    auto& drho = ps[density_rate_];
    auto& v_half = ps[half_velocity_];
    auto& rho_half = ps[half_density_];
    exec::Default::for_each(ps.size(), [&](std::size_t i) {
      if (!ps.is_fluid(i)) return;
      v_half[i] = ps.velocity[i] + 0.5 * dt * a[i];
      rho_half[i] = ps.density[i] + 0.5 * dt * drho[i];
      ps.position[i] += dt * v_half[i];
      ps.velocity[i] = v_half[i] + 0.5 * dt * a[i];
      ps.density[i] = rho_half[i] + 0.5 * dt * drho[i];
      ps.pressure[i] = eos_.pressure(ps.density[i]);
    });
  }

  void kick(ParticleState<D>& s, Real dt) {
    auto& ps = s.particles;
    auto& a = ps[acceleration_];
    auto& drho = ps[density_rate_];
    auto& v_half = ps[half_velocity_];
    auto& rho_half = ps[half_density_];
    exec::Default::for_each(ps.size(), [&](std::size_t i) {
      if (!ps.is_fluid(i)) return;
      ps.velocity[i] = v_half[i] + 0.5 * dt * a[i];
      ps.density[i] = rho_half[i] + 0.5 * dt * drho[i];
      ps.pressure[i] = eos_.pressure(ps.density[i]);
    });
  }

  void measure_extremes(const ParticleState<D>& s) {
    const auto& ps = s.particles;
    const auto& a = ps[acceleration_];
    max_speed_ = exec::Default::max_of(
        ps.size(), [&](std::size_t i) { return ps.is_fluid(i) ? ps.velocity[i].norm() : 0.0; });
    max_acceleration_ = exec::Default::max_of(
        ps.size(), [&](std::size_t i) { return ps.is_fluid(i) ? a[i].norm() : 0.0; });
  }

  // Copies what the pair loops read into the packed single-precision arrays.
  void pack(const ParticleState<D>& s, bool with_rates) {
    const auto& ps = s.particles;
    const auto& wall_velocity = ps[wall_velocity_];
    packed_.resize(ps.size());
    exec::Default::for_each(ps.size(), [&](std::size_t j) {
      const bool fluid = ps.is_fluid(j);
      // 2D models live in the x-z plane: packed as (x, 0, z), like every 3D view of them.
      const Vec3 x = to_3d<D>(ps.position[j]);
      const Vec3 v = to_3d<D>(ps.velocity[j]);
      const Vec3 u = fluid ? v : to_3d<D>(wall_velocity[j]);
      for (int a = 0; a < 3; ++a) {
        packed_.position[a][j] = static_cast<float>(x[a]);
        packed_.velocity[a][j] = static_cast<float>(v[a]);
        packed_.viscous_velocity[a][j] = static_cast<float>(u[a]);
      }
      packed_.density[j] = static_cast<float>(ps.density[j]);
      packed_.pressure[j] = static_cast<float>(ps.pressure[j]);
      packed_.fluid[j] = fluid ? 1.0f : 0.0f;
      packed_.viscous_weight[j] = (fluid || p_.no_slip) ? 1.0f : 0.0f;
      if (with_rates) {
        const Real inverse_rho = 1 / ps.density[j];
        packed_.pressure_term[j] = static_cast<float>(ps.pressure[j] * inverse_rho * inverse_rho);
        packed_.volume[j] = static_cast<float>(ps.mass[j] * inverse_rho);
      }
    });
    packed_.fluid_before[0] = 0;
    for (std::size_t j = 0; j < ps.size(); ++j) {
      packed_.fluid_before[j + 1] = packed_.fluid_before[j] + (ps.is_fluid(j) ? 1 : 0);
    }
  }

  // The walls' pressure, density and viscous velocity from the fluid around them, as the
  // boundary treatment sets them.
  void update_walls(ParticleState<D>& s) {
    pack(s, false);
    WcsphBoundaryContext<D, Kernel> context{s, packed_, kernel_, eos_, s.particles[wall_velocity_]};
    boundary_->update(context);
  }

  // The fluid's force on each body particle w: minus the force that w exerts on its fluid
  // neighbours i, from the very pair term that gives the fluid's acceleration (in double).
  void body_point_forces(const std::vector<BodyKinematics>&,
                         std::vector<Vec3>& force) const override {
    const ParticleState<D>& s = this->state();
    const auto& ps = s.particles;
    const auto p = packed_.view();
    const WcsphPairConstants k = pair_constants(s);
    const Real two_nu_rho0 = 2 * s.kinematic_viscosity * eos_.rho0;
    exec::Default::for_each(ps.size(), [&](std::size_t w) {
      if (ps.body_point[w] < 0) return;
      Vec3 f = Vec3::Zero();
      s.cells.for_each_candidate_range(ps.position[w], [&](std::uint32_t begin, std::uint32_t end) {
        for (std::size_t i = begin; i < end; ++i) {
          if (p.fluid[i] == 0) continue;
          const auto own = own_particle(p, i, two_nu_rho0 / ps.density[i]);
          double ax = 0, ay = 0, az = 0, drho = 0;
          add_wcsph_pair_term(p, own, w, k, kernel_, ax, ay, az, drho);
          f -= ps.mass[i] * Vec3(ax, ay, az);  // minus m_i a_i(w)
        }
      });
      force[ps.body_point[w]] = f;
    });
  }

  // Continuity with density diffusion and the momentum equation, gathered per fluid particle
  // (each pair evaluated from both sides, so no two threads write the same particle).
  void compute_rates(ParticleState<D>& s) {
    pack(s, true);
    auto& ps = s.particles;
    auto& acceleration = ps[acceleration_];
    auto& density_rate = ps[density_rate_];
    const WcsphPairConstants k = pair_constants(s);
    const Vec3 g = to_3d<D>(s.gravity);
    const Real two_nu_rho0 = 2 * s.kinematic_viscosity * eos_.rho0;
    exec::Default::for_each_balanced(ps.size(), [&](std::size_t i) {
      if (!ps.is_fluid(i)) return;
      const float laminar_i = static_cast<float>(two_nu_rho0 / ps.density[i]);
      Rates rates;
      s.cells.for_each_candidate_range(ps.position[i], [&](std::uint32_t begin, std::uint32_t end) {
        add_rates(i, begin, end, k, laminar_i, rates);
      });
      const Vec3 acc(rates.acceleration[0], rates.acceleration[1], rates.acceleration[2]);
      acceleration[i] = from_3d<D>(acc + g);
      density_rate[i] = rates.density;
    });
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

  struct Rates {
    std::array<double, 3> acceleration{};
    double density = 0;
  };

  // The pair terms of fluid particle i with the candidates [begin, end), as SIMD.
  void add_rates(std::size_t i, std::uint32_t begin, std::uint32_t end, const WcsphPairConstants& k,
                 float laminar_i, Rates& out) const {
    const auto p = packed_.view();
    const WcsphOwnParticle<float> own = own_particle(p, i, laminar_i);
    float ax = 0, ay = 0, az = 0, drho = 0;
#pragma omp simd reduction(+ : ax, ay, az, drho)
    for (std::size_t j = begin; j < end; ++j)
      add_wcsph_pair_term(p, own, j, k, kernel_, ax, ay, az, drho);
    out.acceleration[0] += ax;
    out.acceleration[1] += ay;
    out.acceleration[2] += az;
    out.density += drho;
  }

  WcsphParameters p_;
  Kernel kernel_;
  TaitEquation eos_;
  FieldHandle<Vec<D>> acceleration_, half_velocity_, wall_velocity_;
  FieldHandle<Real> density_rate_, half_density_;
  std::unique_ptr<BoundaryTreatment<WcsphBoundaryContext<D, Kernel>>> boundary_;
  PackedParticles packed_;
  Real max_speed_ = 0;
  Real max_acceleration_ = 0;
};

}  // namespace sluice
