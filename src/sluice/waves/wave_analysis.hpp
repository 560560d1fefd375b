// What a wave gauge's record says: its harmonic at a frequency, the incident and reflected
// waves two gauges see (Goda & Suzuki 1976, "Estimation of incident and reflected waves in
// random wave experiments", Proc. 15th ICCE), and a sea's H_m0 and peak period.
#pragma once

#include <complex>
#include <vector>

namespace sluice::waves {

// The complex amplitude Z of the record's part at `omega`: the least-squares fit of
// Re(Z) cos(omega t) + Im(Z) sin(omega t) + mean to (times, values), best over whole periods.
std::complex<double> harmonic(const std::vector<double>& times, const std::vector<double>& values,
                              double omega);

struct IncidentAndReflected {
  double incident = 0, reflected = 0;  // amplitudes [m]
  double coefficient() const { return reflected / incident; }
};

// From the harmonics z1, z2 of wavenumber k at gauges at x1 < x2 (each elevation
// Re(z e^{-i omega t}) = I e^{ikx} + R e^{-ikx}, the incident wave travelling towards +x):
// the two amplitudes. Ill-posed where k (x2 - x1) nears a multiple of pi.
IncidentAndReflected incident_and_reflected(std::complex<double> z1, double x1,
                                            std::complex<double> z2, double x2, double k);

// H_m0 = 4 sqrt(m0), m0 the record's variance about its mean.
double significant_height(const std::vector<double>& values);

// The peak period of an evenly sampled record (spacing dt): the inverse of the power-weighted
// mean frequency of the largest band of `bands_averaged` neighbouring periodogram ordinates (a
// direct Fourier sum at the multiples of 1 / record length up to `max_frequency`).
double peak_period(const std::vector<double>& values, double dt, int bands_averaged,
                   double max_frequency);

}  // namespace sluice::waves
