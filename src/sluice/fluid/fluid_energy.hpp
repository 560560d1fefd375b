// The fluid's energy: what the run's energy.csv records of it, and each particle's share of it,
// read from plain arrays so that the host and a device (wcsph_device_run.hpp) sum the same
// shares.
#pragma once

#include <cstddef>
#include <cstdint>

#include "sluice/core/host_device.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

struct FluidEnergy {
  double kinetic = 0;
  double potential = 0;  // relative to z = 0 along -g, as the bodies'
  double elastic = 0;    // stored in the model's boundary springs (penalty-sph)
  double mass = 0;       // of the fluid [kg]
};

// Particle i's share of one part of the fluid's energy: zero unless it is fluid (kind 0).
// Vector fields hold D reals a particle.
template <int D>
struct FluidEnergyShare {
  enum class Part { kKinetic, kPotential, kMass };
  const Real* mass;
  const Real* position;
  const Real* velocity;
  const std::int32_t* kind;
  Real gravity[D];
  Part part = Part::kKinetic;

  // Over arrays on the host or a device; `g` holds D reals.
  static FluidEnergyShare over(const Real* mass, const Real* position, const Real* velocity,
                               const std::int32_t* kind, const Real* g) {
    FluidEnergyShare share{mass, position, velocity, kind, {}};
    for (int a = 0; a < D; ++a) share.gravity[a] = g[a];
    return share;
  }

  SLUICE_HOST_DEVICE double operator()(std::size_t i) const {
    if (kind[i] != 0) return 0.0;
    const Real* v = velocity + D * i;
    const Real* x = position + D * i;
    double speed2 = 0, height = 0;  // height: g . x, negative above z = 0
    for (int a = 0; a < D; ++a) {
      speed2 += v[a] * v[a];
      height += gravity[a] * x[a];
    }
    switch (part) {
      case Part::kKinetic:
        return 0.5 * mass[i] * speed2;
      case Part::kPotential:
        return -(mass[i] * height);
      default:
        return mass[i];
    }
  }
};

// The fluid's kinetic and potential energy and mass: sum(share) adds up a share over all
// particles (in index order on the host, in a reduction's order on a device).
template <int D, class Sum>
FluidEnergy fluid_energy(FluidEnergyShare<D> share, Sum&& sum) {
  using Part = typename FluidEnergyShare<D>::Part;
  FluidEnergy e;
  share.part = Part::kKinetic;
  e.kinetic = sum(share);
  share.part = Part::kPotential;
  e.potential = sum(share);
  share.part = Part::kMass;
  e.mass = sum(share);
  return e;
}

}  // namespace sluice
