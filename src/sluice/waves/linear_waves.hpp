// Linear (Airy) waves on water of constant depth: the dispersion relation
// omega^2 = g k tanh(k h) and the wave length it gives.
#pragma once

namespace sluice::waves {

// The wavenumber k [1/m] of a wave of angular frequency `omega` [1/s] on water `depth` [m]
// deep under gravity `gravity` [m/s^2]; every argument > 0.
double wavenumber(double omega, double depth, double gravity);

// The angular frequency of a wave of wavenumber `k`.
double angular_frequency(double k, double depth, double gravity);

// The wave height at which a wave of wavenumber k breaks on water `depth` deep (Miche 1944):
// H_max / L = 0.142 tanh(k h).
double breaking_height(double k, double depth);

// The amplitude of the second harmonic bound to a regular wave of amplitude `amplitude`
// (Stokes's second order, e.g. Dean & Dalrymple 1991, ch. 11):
//   eta_2 = (k a^2 / 4) cosh kh (2 + cosh 2kh) / sinh^3 kh  cos 2(kx - omega t).
double stokes_second_harmonic(double amplitude, double k, double depth);

}  // namespace sluice::waves
