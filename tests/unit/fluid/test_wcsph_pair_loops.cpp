// The WCSPH pair loops (single precision, branch-free SIMD over candidate ranges) against a
// plain double-precision loop over every pair within the support, particle by particle, on a
// disturbed lattice with walls and a body. A lane that dropped a pair or counted one twice, or
// a pad or mask that let a particle within reach add a wrong term, would move a rate by a
// whole pair term, on whatever vector width the machine compiles for (SSE, AVX2, AVX-512).
// A lane reading past a candidate range reads a particle beyond the support, which adds zero;
// past the packed arrays, AddressSanitizer stops it (the asan build runs this test).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "sluice/fluid/wcsph/wcsph_model.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/kernels/cubic_spline.hpp"
#include "sluice/kernels/wendland_c2.hpp"
#include "sluice/sim/rigid_bodies.hpp"

namespace sluice {
namespace {

template <int D>
io::CaseConfig disturbed_tank_case(const std::string& kernel, const std::string& slip) {
  const std::string text =
      D == 3 ? "dimension: 3\nspacing: 0.02\ndomain: {min: [0, 0, 0], max: [0.24, 0.2, 0.3]}\n"
               "end_time: 1\noutput_interval: 0.1\n"
               "fluid:\n  blocks:\n    - {min: [0, 0, 0], max: [0.24, 0.2, 0.2]}\n"
               "walls:\n  - {type: tank, min: [0, 0, 0], max: [0.24, 0.2, 0.3], open: [z+]}\n"
               "bodies:\n  - {shape: box, size: [0.06, 0.06, 0.06], density: 800, "
               "position: [0.12, 0.1, 0.12]}\n"
             : "dimension: 2\nspacing: 0.01\ndomain: {min: [0, 0], max: [0.3, 0.3]}\n"
               "end_time: 1\noutput_interval: 0.1\n"
               "fluid:\n  blocks:\n    - {min: [0, 0], max: [0.3, 0.2]}\n"
               "walls:\n  - {type: tank, min: [0, 0], max: [0.3, 0.3], open: [z+]}\n"
               "bodies:\n  - {shape: box, size: [0.05, 0.05], density: 800, "
               "position: [0.15, 0.12]}\n";
  return io::parse_case(text + "model:\n  name: wcsph\n  kernel: " + kernel +
                            "\n  wall_slip: " + slip + "\n  artificial_viscosity: 0.1\n",
                        "pair_loops.yaml");
}

// Rates of every fluid particle and the walls' extrapolated state, in double precision from
// the formulas of WcsphModel (Adami, Hu & Adams 2012 walls; Monaghan's viscosity; laminar
// viscosity; density diffusion with the hydrostatic part removed), over all pairs.
template <int D, class Kernel>
struct Reference {
  std::vector<Vec3> acceleration;
  std::vector<double> density_rate;
  std::vector<double> wall_pressure;

  Reference(const ParticleState<D>& s, const WcsphParameters& p, const Kernel& kernel,
            const TaitEquation& eos) {
    const auto& ps = s.particles;
    const std::size_t n = ps.size();
    const double support2 = kernel.support() * kernel.support();
    const Vec3 g = to_3d<D>(s.gravity);
    std::vector<double> rho(ps.density), pressure(ps.pressure);
    std::vector<Vec3> viscous(n);
    wall_pressure.assign(n, 0);
    for (std::size_t w = 0; w < n; ++w) {
      viscous[w] = to_3d<D>(ps.velocity[w]);
      if (ps.is_fluid(w)) continue;
      double weight = 0, sum_p = 0;
      Vec3 rho_r = Vec3::Zero(), velocity = Vec3::Zero();
      for (std::size_t f = 0; f < n; ++f) {
        const Vec3 r = to_3d<D>(ps.position[w] - ps.position[f]);
        if (!ps.is_fluid(f) || r.squaredNorm() >= support2) continue;
        const double W = kernel.value(r.norm());
        weight += W;
        sum_p += ps.pressure[f] * W;
        rho_r += ps.density[f] * W * r;
        velocity += W * to_3d<D>(ps.velocity[f]);
      }
      Vec3 g_wall = g;
      if (ps.body_point[w] >= 0) g_wall -= s.body_point_acceleration[ps.body_point[w]];
      pressure[w] = weight > 0 ? std::max((sum_p + g_wall.dot(rho_r)) / weight, eos.lowest) : 0;
      rho[w] = weight > 0 ? eos.density(pressure[w]) : eos.rho0;
      if (weight > 0) viscous[w] = 2 * to_3d<D>(ps.velocity[w]) - velocity / weight;
      wall_pressure[w] = pressure[w];
    }
    const double h = kernel.h, c0 = eos.c0;
    const double eta2 = 0.01 * h * h, two_alpha_c0_h = 2 * p.artificial_viscosity * c0 * h;
    const double diffusion = -2 * p.density_diffusion * h * c0;
    const Vec3 hydrostatic = -(eos.rho0 / (c0 * c0)) * g;
    acceleration.assign(n, Vec3::Zero());
    density_rate.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      if (!ps.is_fluid(i)) continue;
      const double laminar_i = 2 * s.kinematic_viscosity * eos.rho0 / rho[i];
      const double pressure_term_i = pressure[i] / (rho[i] * rho[i]);
      Vec3 a = Vec3::Zero();
      double drho = 0;
      for (std::size_t j = 0; j < n; ++j) {
        const Vec3 r = to_3d<D>(ps.position[i] - ps.position[j]);
        const double r2 = r.squaredNorm();
        if (j == i || r2 >= support2) continue;
        const double f = kernel.gradient_factor(std::sqrt(r2));
        const double volume_j = ps.mass[j] / rho[j];
        const bool fluid_j = ps.is_fluid(j);
        const double viscous_weight = fluid_j || p.no_slip ? 1 : 0;
        const Vec3 u = to_3d<D>(ps.velocity[i]) - viscous[j];
        const double v_dot_r = to_3d<D>(ps.velocity[i] - ps.velocity[j]).dot(r);
        drho += rho[j] * volume_j * f * v_dot_r;
        if (fluid_j) drho += diffusion * (rho[j] - rho[i] - hydrostatic.dot(r)) * f * volume_j;
        const double inverse_r2 = 1 / (r2 + eta2);
        const double artificial =
            -two_alpha_c0_h * std::min(u.dot(r), 0.0) * inverse_r2 / (rho[i] + rho[j]);
        const double push =
            rho[j] * volume_j *
            (pressure_term_i + pressure[j] / (rho[j] * rho[j]) + viscous_weight * artificial) * f;
        const double laminar = viscous_weight * volume_j * laminar_i * r2 * f * inverse_r2;
        a += laminar * u - push * r;
      }
      acceleration[i] = a + g;
      density_rate[i] = drho;
    }
  }
};

struct Deviation {
  double acceleration = 0, density_rate = 0, wall_pressure = 0;
  double acceleration_scale = 0, density_rate_scale = 0, wall_pressure_scale = 0;
};

// Builds the case, shakes the fluid (positions by up to a quarter spacing, speeds of up to
// 0.5 m/s, pressures by up to 20 %), evaluates the model's first rates and compares.
template <int D, class Kernel>
Deviation compare_with_reference(const std::string& kernel_name, const std::string& slip) {
  const io::CaseConfig config = disturbed_tank_case<D>(kernel_name, slip);
  const WcsphParameters p = read_wcsph_parameters(config);
  const RigidBodies bodies(config);
  WcsphModel<D, Kernel> model(p, config, bodies);
  ParticleState<D>& s = model.state();
  auto& ps = s.particles;
  std::mt19937 random(12345);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (!ps.is_fluid(i)) continue;
    for (int a = 0; a < D; ++a) {
      ps.position[i][a] += 0.25 * config.spacing * unit(random);
      ps.velocity[i][a] = 0.5 * unit(random);
    }
    ps.pressure[i] *= 1 + 0.2 * unit(random);
  }
  std::vector<std::uint32_t> order;
  s.cells.sort(ps.position, order);
  ps.reorder(order);
  model.initialize();  // wall states and the first rates

  const Kernel kernel(p.smoothing_length(config.spacing));
  const TaitEquation eos(config.fluid.density, p.sound_speed, p.gamma);
  const Reference<D, Kernel> reference(s, p, kernel, eos);
  const auto& acceleration = ps[model.acceleration_field()];
  const auto& density_rate = ps[model.density_rate_field()];
  Deviation out;
  for (std::size_t i = 0; i < ps.size(); ++i) {
    if (ps.is_fluid(i)) {
      out.acceleration = std::max(out.acceleration,
                                  (to_3d<D>(acceleration[i]) - reference.acceleration[i]).norm());
      out.density_rate =
          std::max(out.density_rate, std::abs(density_rate[i] - reference.density_rate[i]));
      out.acceleration_scale = std::max(out.acceleration_scale, reference.acceleration[i].norm());
      out.density_rate_scale =
          std::max(out.density_rate_scale, std::abs(reference.density_rate[i]));
    } else {
      out.wall_pressure =
          std::max(out.wall_pressure, std::abs(ps.pressure[i] - reference.wall_pressure[i]));
      out.wall_pressure_scale =
          std::max(out.wall_pressure_scale, std::abs(reference.wall_pressure[i]));
    }
  }
  std::printf(
      "%dD %s %s: largest deviation from the double loop: acceleration %.3g of %.3g m/s^2, "
      "density rate %.3g of %.3g kg/m^3/s, wall pressure %.3g of %.3g Pa\n",
      D, kernel_name.c_str(), slip.c_str(), out.acceleration, out.acceleration_scale,
      out.density_rate, out.density_rate_scale, out.wall_pressure, out.wall_pressure_scale);
  return out;
}

// Single precision keeps about 7 digits; sums of some 30-60 pair terms that cancel to the
// rates lose one or two more. A stray or missing pair moves a rate by a sizeable part of its
// scale, far above these bounds.
void expect_single_precision_agreement(const Deviation& d) {
  EXPECT_LT(d.acceleration, 1e-4 * d.acceleration_scale);
  EXPECT_LT(d.density_rate, 1e-4 * d.density_rate_scale);
  EXPECT_LT(d.wall_pressure, 1e-5 * d.wall_pressure_scale);
}

TEST(WcsphPairLoops, MatchDoubleLoopIn3DWendland) {
  expect_single_precision_agreement(
      compare_with_reference<3, WendlandC2<3>>("wendland", "no_slip"));
}

TEST(WcsphPairLoops, MatchDoubleLoopIn3DCubicSplineFreeSlip) {
  expect_single_precision_agreement(
      compare_with_reference<3, CubicSpline<3>>("cubic_spline", "free_slip"));
}

TEST(WcsphPairLoops, MatchDoubleLoopIn2D) {
  expect_single_precision_agreement(
      compare_with_reference<2, WendlandC2<2>>("wendland", "no_slip"));
}

}  // namespace
}  // namespace sluice
