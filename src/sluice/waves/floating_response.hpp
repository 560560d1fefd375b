// The heave of a box floating in regular waves by linear theory, in the Froude–Krylov
// approximation that holds for a box long compared with its draft in waves long compared with
// it (e.g. Journée & Massie 2001, "Offshore Hydromechanics", ch. 6).
#pragma once

namespace sluice::waves {

// The heave amplitude per unit incident amplitude of a 2D box `beam` [m] long (along the waves)
// floating at `draft` [m], held to heave only, in regular waves of wavenumber k and angular
// frequency omega on water `depth` deep. The incident wave's pressure under the box's bottom,
// integrated over its beam, gives the exciting force
//   F = rho g a B cosh(k (h - d)) / cosh(k h) sin(k B / 2) / (k B / 2);
// against it stand the waterplane's stiffness rho g B and the box's inertia (mass rho B d per
// unit width). An added mass rho B m_a (`added_mass_depth` = m_a [m]) enters both sides, as the
// diffraction force of a body small against the wave is the added mass times the water's
// acceleration there, so the response is
//   Z / a = f / (1 - w d / (1 - w m_a)),  w = omega^2 / g,
// f the force's factor above: the added mass moves it at second order in omega^2 d / g.
double box_heave_response(double k, double omega, double depth, double gravity, double beam,
                          double draft, double added_mass_depth = 0);

}  // namespace sluice::waves
