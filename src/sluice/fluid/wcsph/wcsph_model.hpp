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
#include "sluice/fluid/fluid_model.hpp"
#include "sluice/fluid/wcsph/tait.hpp"
#include "sluice/fluid/wcsph/wcsph_parameters.hpp"

namespace sluice {

template <int D, class Kernel>
class WcsphModel final : public FluidModel<D> {
 public:
  WcsphModel(const WcsphParameters& parameters, const io::CaseConfig& config)
      : p_(parameters),
        kernel_(parameters.smoothing_length(config.spacing)),
        eos_(config.fluid.density, parameters.sound_speed, parameters.gamma) {}

  Real interaction_radius() const override { return kernel_.support(); }

  std::string describe() const override {
    return fmt::format(
        "wcsph: kernel {}, h = {:.4g} m ({} dx), c0 = {:.4g} m/s, alpha = {}, delta = {}, "
        "walls {}",
        Kernel::kName, kernel_.h, p_.h_over_dx, eos_.c0, p_.artificial_viscosity,
        p_.density_diffusion, p_.no_slip ? "no-slip" : "free-slip");
  }

  void initialize(SimulationState<D>& s) override {
    auto& ps = s.particles;
    acceleration_ = ps.add_vector_field();
    density_rate_ = ps.add_scalar_field();
    half_velocity_ = ps.add_vector_field();
    half_density_ = ps.add_scalar_field();
    wall_velocity_ = ps.add_vector_field();
    pressure_term_ = ps.add_scalar_field();
    volume_ = ps.add_scalar_field();
    // The builder set a hydrostatic pressure; the density follows from the equation of state.
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (ps.is_fluid(i)) ps.density[i] = eos_.density(ps.pressure[i]);
    }
    update_walls(s);
    compute_rates(s);
    measure_extremes(s);
  }

  void append_stages(std::vector<std::unique_ptr<Stage<D>>>& before,
                     std::vector<std::unique_ptr<Stage<D>>>& after) override {
    before.push_back(make_stage<D>("kick_drift", [this](SimulationState<D>& s) { kick_drift(s); }));
    after.push_back(
        make_stage<D>("wall_state", [this](SimulationState<D>& s) { update_walls(s); }));
    after.push_back(make_stage<D>("forces", [this](SimulationState<D>& s) { compute_rates(s); }));
    after.push_back(make_stage<D>("kick", [this](SimulationState<D>& s) {
      kick(s);
      measure_extremes(s);
    }));
  }

  double next_time_step(const SimulationState<D>& s) const override {
    const Real h = kernel_.h;
    double dt = p_.cfl * h / (eos_.c0 + max_speed_);
    if (max_acceleration_ > 0) dt = std::min(dt, p_.force_cfl * std::sqrt(h / max_acceleration_));
    if (s.kinematic_viscosity > 0) dt = std::min(dt, 0.125 * h * h / s.kinematic_viscosity);
    return dt;
  }

 private:
  // First half kick and drift; velocity and density are then predicted to the end of the
  // step for the force evaluation, which keeps one force evaluation per step.
  void kick_drift(SimulationState<D>& s) {
    auto& ps = s.particles;
    auto& a = ps[acceleration_];
    auto& drho = ps[density_rate_];
    auto& v_half = ps[half_velocity_];
    auto& rho_half = ps[half_density_];
    const Real dt = s.dt;
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

  void kick(SimulationState<D>& s) {
    auto& ps = s.particles;
    auto& a = ps[acceleration_];
    auto& drho = ps[density_rate_];
    auto& v_half = ps[half_velocity_];
    auto& rho_half = ps[half_density_];
    const Real dt = s.dt;
    exec::Default::for_each(ps.size(), [&](std::size_t i) {
      if (!ps.is_fluid(i)) return;
      ps.velocity[i] = v_half[i] + 0.5 * dt * a[i];
      ps.density[i] = rho_half[i] + 0.5 * dt * drho[i];
      ps.pressure[i] = eos_.pressure(ps.density[i]);
    });
  }

  void measure_extremes(const SimulationState<D>& s) {
    const auto& ps = s.particles;
    const auto& a = ps[acceleration_];
    max_speed_ = exec::Default::max_of(
        ps.size(), [&](std::size_t i) { return ps.is_fluid(i) ? ps.velocity[i].norm() : 0.0; });
    max_acceleration_ = exec::Default::max_of(
        ps.size(), [&](std::size_t i) { return ps.is_fluid(i) ? a[i].norm() : 0.0; });
  }

  // Adami, Hu & Adams (2012): wall pressure from the fluid around it, with the hydrostatic
  // correction; wall density from the inverse equation of state; for no-slip, the wall's
  // viscous velocity mirrors the fluid's Shepard-averaged velocity about the wall's own.
  void update_walls(SimulationState<D>& s) {
    auto& ps = s.particles;
    auto& wall_velocity = ps[wall_velocity_];
    const Real radius2 = kernel_.support() * kernel_.support();
    const Vec<D> g = s.gravity;
    exec::Default::for_each(ps.size(), [&](std::size_t w) {
      if (ps.is_fluid(w)) return;
      Real sum_w = 0, sum_pw = 0;
      Vec<D> sum_rho_r_w = Vec<D>::Zero(), sum_v_w = Vec<D>::Zero();
      s.cells.for_each_neighbor(ps.position, w, radius2,
                                [&](std::size_t f, const Vec<D>& r_wf, Real r2) {
                                  if (!ps.is_fluid(f)) return;
                                  const Real weight = kernel_.value(std::sqrt(r2));
                                  sum_w += weight;
                                  sum_pw += ps.pressure[f] * weight;
                                  sum_rho_r_w += (ps.density[f] * weight) * r_wf;
                                  sum_v_w += weight * ps.velocity[f];
                                });
      if (sum_w > 0) {
        // Fixed walls do not accelerate; moving bodies will pass their acceleration here.
        const Real p = (sum_pw + g.dot(sum_rho_r_w)) / sum_w;
        ps.pressure[w] = p;
        ps.density[w] = eos_.density(p);
        wall_velocity[w] = 2 * ps.velocity[w] - sum_v_w / sum_w;
      } else {
        ps.pressure[w] = 0;
        ps.density[w] = eos_.rho0;
        wall_velocity[w] = ps.velocity[w];
      }
    });
  }

  // Continuity with density diffusion and the momentum equation, gathered per fluid particle
  // (each pair evaluated from both sides, so no two threads write the same particle).
  // Per-particle factors are computed first so the pair loop has a single division.
  void compute_rates(SimulationState<D>& s) {
    auto& ps = s.particles;
    auto& pressure_term = ps[pressure_term_];
    auto& volume = ps[volume_];
    exec::Default::for_each(ps.size(), [&](std::size_t j) {
      const Real inverse_rho = 1 / ps.density[j];
      pressure_term[j] = ps.pressure[j] * inverse_rho * inverse_rho;
      volume[j] = ps.mass[j] * inverse_rho;
    });
    auto& acceleration = ps[acceleration_];
    auto& density_rate = ps[density_rate_];
    const auto& wall_velocity = ps[wall_velocity_];
    const Real h = kernel_.h;
    const Real radius2 = kernel_.support() * kernel_.support();
    const Real eta2 = 0.01 * h * h;
    const Real c0 = eos_.c0;
    const Real two_alpha_c0_h = 2 * p_.artificial_viscosity * c0 * h;
    // Molteni & Colagrossi (2009) diffusion, with the hydrostatic part of the density
    // difference removed (Fourtakas et al. 2019), linearised: rho_H_ji = rho0 g.r_ji / c0^2.
    const Real diffusion = -2 * p_.density_diffusion * h * c0;
    const Vec<D> hydrostatic = -(eos_.rho0 / (c0 * c0)) * s.gravity;  // rho_H_ji = this . r_ij
    const Real two_nu_rho0 = 2 * s.kinematic_viscosity * eos_.rho0;
    const bool no_slip = p_.no_slip;
    const Vec<D> g = s.gravity;
    exec::Default::for_each(ps.size(), [&](std::size_t i) {
      if (!ps.is_fluid(i)) return;
      const Vec<D> v_i = ps.velocity[i];
      const Real rho_i = ps.density[i];
      const Real laminar_i = two_nu_rho0 / rho_i;
      const Real pressure_term_i = pressure_term[i];
      Vec<D> acc = Vec<D>::Zero();
      Real drho = 0;
      s.cells.for_each_neighbor(ps.position, i, radius2, [&](std::size_t j, const Vec<D>& r_ij, Real r2) {
        const Real f = kernel_.gradient_factor(std::sqrt(r2));
        const Real v_j = volume[j];
        const Real rho_j = ps.density[j];
        const bool fluid_j = ps.is_fluid(j);
        const Vec<D> v_ij = v_i - ps.velocity[j];
        drho += rho_j * v_j * f * v_ij.dot(r_ij);  // m_j v_ij . grad W
        Real coefficient = pressure_term_i + pressure_term[j];
        if (fluid_j) drho += diffusion * (rho_j - rho_i - hydrostatic.dot(r_ij)) * f * v_j;
        if (fluid_j || no_slip) {
          const Vec<D> v_visc = fluid_j ? v_ij : Vec<D>(v_i - wall_velocity[j]);
          const Real vr = v_visc.dot(r_ij);
          const Real inverse_r2 = 1 / (r2 + eta2);
          if (vr < 0) coefficient -= two_alpha_c0_h * vr * inverse_r2 / (rho_i + rho_j);
          acc += (v_j * laminar_i * r2 * f * inverse_r2) * v_visc;
        }
        acc -= (rho_j * v_j * coefficient * f) * r_ij;
      });
      acceleration[i] = acc + g;
      density_rate[i] = drho;
    });
  }

  WcsphParameters p_;
  Kernel kernel_;
  TaitEquation eos_;
  FieldHandle<Vec<D>> acceleration_, half_velocity_, wall_velocity_;
  FieldHandle<Real> density_rate_, half_density_;
  FieldHandle<Real> pressure_term_, volume_;  // p / rho^2 and m / rho, refreshed every step
  Real max_speed_ = 0;
  Real max_acceleration_ = 0;
};

}  // namespace sluice
