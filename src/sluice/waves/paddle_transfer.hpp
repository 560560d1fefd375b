// Wavemaker theory: the stroke a paddle needs for a wave of a given height. Biésel & Suquet
// (1951), in Dean & Dalrymple, "Water Wave Mechanics for Engineers and Scientists" (1991), ch. 6:
// a paddle whose displacement at depth z below the still water line is X f(z) (f(0) = 1) makes
// a progressive wave of height
//   H / S = 4 sinh(kh) / (sinh 2kh + 2kh) * integral_{-h}^{0} f(z) k cosh k(h + z) dz,
// S = 2 X the stroke at the still water line. A piston has f = 1; a flap hinged `d` below the
// still water line f = 1 + z / d above the hinge (0 below it, where the hinge is above the bed).
#pragma once

#include <limits>

namespace sluice::waves {

// A piston's hinge depth: it does not turn.
inline constexpr double kPistonHinge = std::numeric_limits<double>::infinity();

// H / S for wavenumber k on water `depth` deep, for a flap hinged `hinge_depth` below the still
// water line (above, at or below the bed), or a piston (kPistonHinge).
double height_over_stroke(double k, double depth, double hinge_depth);

// Madsen (1971, "On the generation of long waves", J. Geophys. Res. 76): a piston moving as
// (S/2) sin(omega t) also sends out a free wave at 2 omega, which its second-order theory
// cancels by adding X2 sin(2 omega t) with
//   X2 = H^2 / (32 h) (3 cosh kh / sinh^3 kh - 2 / (H/S)),
// the amplitude returned here [m] (as written by Altomare et al. 2017, Coastal Eng. 127, eq. 8).
double madsen_second_harmonic(double height, double k, double depth);

}  // namespace sluice::waves
