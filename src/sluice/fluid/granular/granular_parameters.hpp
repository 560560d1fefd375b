// Parameters of the granular model (seed 001's fourth method), read from the case's `model:`
// mapping. Defaults, meanings and sources are documented in docs/case-format.md.
#pragma once

#include "sluice/io/case_config.hpp"

namespace sluice {

struct GranularParameters {
  double radius = 0;  // of every sphere [m]; 0 = 0.49 of the spacing
  // Each sphere starts moved sideways by up to this share of the room the lattice leaves it,
  // (dx / 2 - r), in a fixed pseudo-random way: a perfect lattice of frictionless spheres
  // stands in columns like a crystal; shaken, it flows.
  double jitter = 1;
  // Radii spread uniformly over [1 - size_spread, 1] times `radius`, in a fixed pseudo-random
  // way: equal discs (2D) crystallise into a solid; a spread keeps the packing amorphous.
  double size_spread = 0;
  // Where the random stream of the jitter and the radii starts: another seed is another packing
  // of the same statistics (a check averages its figure over several).
  int packing_seed = 0;
  double friction = 0;  // Coulomb mu between spheres (with a wall or body: the smaller)
  double cohesion = 0;  // the pull a contact holds [N]
  // Rolling resistance mu_r: a contact resists rolling and spinning with up to mu_r times the
  // pair's reduced radius times its normal force (only with friction). Real grains are
  // angular and hardly roll; a frictional disc rolls on forever.
  double rolling_friction = 0;
  // Newton's restitution of a sphere-sphere impact: the pair separates at e times the speed
  // it met with (impacts faster than gravity brings in two steps). 0: perfectly plastic, the
  // complementarity step's own.
  double restitution = 0.9;
  double time_step = 0;    // a fixed step [s]; 0 = cfl r / the fastest speed
  double cfl = 0.1;        // of a radius a sphere may move in a step
  double envelope = 0.25;  // contacts are looked for up to this many radii apart
  double max_speed = 0;    // the speed scale [m/s]; 0 = the free-fall speed sqrt(2 g H)
  // Where the complementarity solve runs: the host, or the emulated device's copy of the
  // problem (ccp/device_ccp_problem.hpp), which gives the same answer to the bit.
  bool emulated_device = false;
};

GranularParameters read_granular_parameters(const io::CaseConfig& config);

// The case as the granular model needs it: the complementarity contact method (an input error
// when the case asks for the penalty one).
void prepare_granular_case(io::CaseConfig& config);

}  // namespace sluice
