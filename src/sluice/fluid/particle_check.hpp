// The check for a particle gone wrong, as a loop body for the host and the device: a position,
// velocity, density or pressure that is not finite, or a fluid particle out of the domain grown
// by the walls.
#pragma once

#include <cmath>
#include <cstdint>

#include "sluice/core/host_device.hpp"
#include "sluice/core/types.hpp"

namespace sluice {

// What is wrong with particle i, if anything: a code that particle_problem_text names.
enum class ParticleProblem : int { kNone = 0, kPosition, kVelocity, kDensityOrPressure, kEscaped };

template <int D>
struct ParticleCheck {
  const Real* position;  // D per particle
  const Real* velocity;
  const Real* density;
  const Real* pressure;
  const std::int32_t* kind;           // 0 is fluid
  Real escape_min[D], escape_max[D];  // the domain grown by the walls, in the model's axes
  SLUICE_HOST_DEVICE ParticleProblem operator()(std::size_t i) const {
    for (int a = 0; a < D; ++a)
      if (!std::isfinite(position[D * i + a])) return ParticleProblem::kPosition;
    for (int a = 0; a < D; ++a)
      if (!std::isfinite(velocity[D * i + a])) return ParticleProblem::kVelocity;
    if (!std::isfinite(density[i]) || !std::isfinite(pressure[i]))
      return ParticleProblem::kDensityOrPressure;
    if (kind[i] != 0) return ParticleProblem::kNone;
    for (int a = 0; a < D; ++a) {
      const Real x = position[D * i + a];
      if (x < escape_min[a] || x > escape_max[a]) return ParticleProblem::kEscaped;
    }
    return ParticleProblem::kNone;
  }
};

inline const char* particle_problem_text(ParticleProblem p) {
  switch (p) {
    case ParticleProblem::kPosition:
      return "its position is not finite";
    case ParticleProblem::kVelocity:
      return "its velocity is not finite";
    case ParticleProblem::kDensityOrPressure:
      return "its density or pressure is not finite";
    case ParticleProblem::kEscaped:
      return "it left the domain";
    case ParticleProblem::kNone:
      break;
  }
  return nullptr;
}

}  // namespace sluice
