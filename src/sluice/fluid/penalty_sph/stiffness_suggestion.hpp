// The smallest penalty stiffness Ks that holds a fluid particle back at a layer of solid
// particles (seed 002's question, answered by energy): the penalty force Ks d n is the
// gradient of the energy Ks d^2 / 2, so a particle striking the layer gets through only where
// its kinetic energy m v^2 / 2 beats the springs' energy at the layer's weakest point, the
// centre of a pore of the square lattice (a gap of the row in 2D). There the energy is
// Ks * barrier, barrier = sum over the solid particles within reach of (reach - r)^2 / 2.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "sluice/core/types.hpp"
#include "sluice/fluid/penalty_sph/penalty_sph_parameters.hpp"
#include "sluice/io/case_config.hpp"

namespace sluice {

// `barrier` [m^2] of a square lattice (D = 3) or row (D = 2) of solid particles `spacing`
// apart touching a fluid particle at `reach`: the least, over the lattice's cell, of the sum
// of (reach - r)^2 / 2 over the solid particles in its plane.
template <int D>
Real penalty_barrier(Real spacing, Real reach) {
  const int n = static_cast<int>(std::ceil(reach / spacing)) + 1;
  constexpr int kSamples = 20;
  Real least = std::numeric_limits<Real>::infinity();
  for (int a = 0; a <= kSamples; ++a) {
    for (int b = 0; b <= (D == 3 ? kSamples : 0); ++b) {
      const Real u = 0.5 * spacing * a / kSamples, w = 0.5 * spacing * b / kSamples;
      Real sum = 0;
      for (int i = -n; i <= n; ++i) {
        for (int j = (D == 3 ? -n : 0); j <= (D == 3 ? n : 0); ++j) {
          const Real r = std::hypot(u - i * spacing, w - j * spacing);
          if (r < reach) sum += 0.5 * (reach - r) * (reach - r);
        }
      }
      least = std::min(least, sum);
    }
  }
  return least;
}

// The smallest Ks [N/m] that stops a particle of mass m arriving at speed v; infinite when
// the pores are wider than the reach (barrier 0).
inline Real suggested_penalty_stiffness(Real barrier, Real mass, Real speed) {
  if (barrier <= 0) return std::numeric_limits<Real>::infinity();
  return 0.5 * mass * speed * speed / barrier;
}

// The energy rule for Ks when the case gives none: a particle of mass m arriving at the largest
// expected speed is stopped by one solid particle of its own spacing within a quarter spacing,
// 1/2 Ks d^2 = 1/2 m v^2.
inline Real energy_rule_stiffness(Real mass, Real max_speed, Real spacing) {
  return mass * std::pow(max_speed / (0.25 * spacing), 2);
}

// For the run's description, one line per solid layer: the smallest Ks that holds back the
// fastest expected impact, a fluid block falling from its top onto the layer's top at its
// initial speed or from rest; or that none does.
template <int D>
std::string layer_stiffness_advice(const PenaltySphParameters& p, const io::CaseConfig& config,
                                   Real particle_mass) {
  std::string out;
  const double g = config.gravity.norm();
  for (const SolidLayerConfig& layer : p.solids) {
    double speed = 0;
    for (const auto& block : config.fluid.blocks) {
      const double drop = std::max(0.0, block.box.max[2] - layer.box.max[2]);
      speed = std::max(speed, std::sqrt(block.velocity.squaredNorm() + 2 * g * drop));
    }
    const Real spacing = layer.spacing_ratio * config.spacing;
    const Real ks = suggested_penalty_stiffness(
        penalty_barrier<D>(spacing, (spacing + config.spacing) / 2), particle_mass, speed);
    out += std::isinf(ks) ? fmt::format(
                                "\n  {}: no Ks holds the fluid back: the gaps between the solid "
                                "particles are wider than the reach (L_b + l0)/2",
                                layer.key)
                          : fmt::format(
                                "\n  {}: Ks >= {:.3g} N/m holds the fluid back (the springs' "
                                "energy at the centre of a gap beats m v^2/2 at v = {:.3g} m/s)",
                                layer.key, ks, speed);
  }
  return out;
}

}  // namespace sluice
