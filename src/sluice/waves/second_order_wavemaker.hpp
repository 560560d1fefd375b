// Schäffer's (1996, "Second-order wavemaker theory for irregular waves", Ocean Eng. 23, 47-88)
// superharmonic transfer function for one regular wave: a paddle moving as (S/2) sin(omega t +
// phase) at the still water line makes, besides its first-order wave of amplitude a, a spurious
// free wave at 2 omega; adding
//   X2(t) = a^2 |F| sin(2 (omega t + phase) + arg F)
// to its displacement cancels it. F [1/m] sums over the first-order wave's progressive and
// evanescent modes (k_0 = k, k_j = -i kappa_j with omega^2 = -g kappa_j tan(kappa_j h)) with
// the free wavenumber K at 2 omega: eqs. (41a-c), (36b), (25d), (20), (21), for a flap hinged D
// below the still water line (above, at or below the bed) or a piston (D infinite). Its
// piston's shallow-water limit is Madsen's (1971) formula (paddle_transfer.hpp); beyond kh of
// about 0.3 the evanescent modes part them (at kh = 1 Madsen's is a quarter of Schäffer's).
// docs/notes/flap_second_order.md derives it and lists the checks of it.
#pragma once

#include <complex>

namespace sluice::waves {

// F of Schäffer's theory for a wave of angular frequency `omega` on water `depth` deep, the
// paddle hinged `hinge_depth` below the still water line (kPistonHinge: a piston). The sums run
// over `modes` evanescent modes twice (modes, 2 modes) and are extrapolated (they converge as
// 1 / modes; 400: within 1e-4 of the limit).
std::complex<double> schaffer_second_order(double omega, double depth, double hinge_depth,
                                           double gravity, int modes = 400);

}  // namespace sluice::waves
