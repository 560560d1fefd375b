// Advection of grid values by the face velocities: semi-Lagrangian (trace each point back
// along the flow, second-order Runge-Kutta, and sample there), and MacCormack's predictor-
// corrector on top of it with the limiter of Selle, Fedkiw, Kim, Liu & Rossignac (J. Sci.
// Comput. 35, 2008): second order where the field is smooth, never a new extremum.
#pragma once

#include <algorithm>
#include <vector>

#include "sluice/exec/policy.hpp"
#include "sluice/fluid/mac/mac_grid.hpp"

namespace sluice {

// Where the flow `u` carried the point at x from, `dt` ago (midpoint rule).
template <int D>
Vec<D> trace_back(const MacGrid<D>& grid, const std::type_identity_t<FaceField<D>>& u,
                  const Vec<D>& x, Real dt) {
  const Vec<D> middle = x - 0.5 * dt * velocity_at(grid, u, x);
  return x - dt * velocity_at(grid, u, middle);
}

// The values of `lattice` after one semi-Lagrangian step of `dt` (dt < 0 traces forward);
// `low`/`high`, when given, receive the range of the values each sample was drawn from.
template <int D>
std::vector<Real> advect_semi_lagrangian(const Lattice<D>& lattice, const std::vector<Real>& values,
                                         const MacGrid<D>& grid,
                                         const std::type_identity_t<FaceField<D>>& u, Real dt,
                                         std::vector<Real>* low = nullptr,
                                         std::vector<Real>* high = nullptr) {
  std::vector<Real> out(values.size());
  if (low != nullptr) low->resize(values.size());
  if (high != nullptr) high->resize(values.size());
  exec::Default::for_each(values.size(), [&](std::size_t k) {
    const Vec<D> from = trace_back(grid, u, lattice.position(lattice.coordinates(k)), dt);
    Real lo, hi;
    out[k] = lattice.sample(values, from, &lo, &hi);
    if (low != nullptr) (*low)[k] = lo;
    if (high != nullptr) (*high)[k] = hi;
  });
  return out;
}

// MacCormack: the semi-Lagrangian prediction, corrected by half the error that a backward step
// finds in it; where the correction would leave the range of the values the prediction was
// drawn from, the prediction itself (Selle et al.'s revert). Clamped into that range instead,
// the velocity beside the free surface and the solids kept energy it should have lost: F3 at
// cells of 0.04 m gained 36 % from 1.9 to 2.5 s, and at 0.02 m diverged near 1.9 s.
template <int D>
std::vector<Real> advect_maccormack(const Lattice<D>& lattice, const std::vector<Real>& values,
                                    const MacGrid<D>& grid,
                                    const std::type_identity_t<FaceField<D>>& u, Real dt) {
  std::vector<Real> low, high;
  std::vector<Real> predicted = advect_semi_lagrangian(lattice, values, grid, u, dt, &low, &high);
  const std::vector<Real> returned = advect_semi_lagrangian(lattice, predicted, grid, u, -dt);
  exec::Default::for_each_light(values.size(), [&](std::size_t k) {
    const Real corrected = predicted[k] + 0.5 * (values[k] - returned[k]);
    if (corrected >= low[k] && corrected <= high[k]) predicted[k] = corrected;
  });
  return predicted;
}

}  // namespace sluice
