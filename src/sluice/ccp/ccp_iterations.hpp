// The complementarity solvers (ccp_solver.hpp), written once over a space that holds the problem
// and its vectors where the solve runs: the host's (host_ccp_space.hpp) or a device's
// (device_ccp_problem.hpp). A space offers
//   Space::Vector              n reals: resize(n), data(), swap(other)
//   size()                     n, the unknowns
//   copy(to, from)             to = from
//   gradient(x, g)             g = N x + r, and the bodies' velocities after the impulses x
//   project(x), diagonal(d), warm_start(x), store(x)   as CcpProblem's
//   for_each(n, body), sum_of(n, value), max_of(n, value)   loops, sums in fixed blocks
// Both spaces run the same steps (ccp_steps.hpp) in the same order, so a device run on the
// host's threads takes the host's iterates to the bit.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "sluice/ccp/ccp_solver.hpp"
#include "sluice/ccp/ccp_steps.hpp"

namespace sluice::ccp_iterations {

template <class Space>
using Vector = typename Space::Vector;

// alpha of the residual: a thousandth of the smallest effective mass of a row (1 / the largest
// of the diagonal).
template <class Space>
Real residual_alpha(Space& s, const Vector<Space>& diagonal) {
  const Real largest = s.max_of(s.size(), ccp_steps::Element{diagonal.data()});
  return largest > 0 ? 1e-3 / largest : 1e-3;
}

// The velocity-level residual of gamma with gradient g [m/s]: the largest component of
// (gamma - P(gamma - alpha g)) / alpha, which tends, as alpha -> 0, to each active row's
// velocity error and each inactive row's violation (0 for a row that separates).
template <class Space>
Real residual(Space& s, const Vector<Space>& gamma, const Vector<Space>& g, Real alpha,
              Vector<Space>& scratch) {
  const std::size_t n = s.size();
  s.for_each(n, ccp_steps::ResidualTrial{gamma.data(), g.data(), alpha, scratch.data()});
  s.project(scratch);
  return s.max_of(n, ccp_steps::ResidualGap{gamma.data(), scratch.data()}) / alpha;
}

// The end of either solver: the best impulses go to the groups, the bodies' velocities after
// them are the space's.
template <class Space>
CcpResult finish(Space& s, const Vector<Space>& best, Real best_residual, int iterations,
                 const CcpSettings& settings, Vector<Space>& scratch) {
  s.gradient(best, scratch);
  s.store(best);
  return {std::min(iterations, settings.max_iterations), best_residual};
}

// APGD (apgd.cpp describes it).
template <class Space>
CcpResult apgd(Space& s, const CcpSettings& settings) {
  using namespace ccp_steps;
  const std::size_t n = s.size();
  Vector<Space> gamma, gamma_new, y, g_y, g_new, r, best, scratch, diag, inverse, probe;
  for (Vector<Space>* v :
       {&gamma, &gamma_new, &y, &g_y, &g_new, &r, &best, &scratch, &diag, &inverse, &probe})
    v->resize(n);
  CcpResult out;
  if (n == 0) {
    s.gradient(gamma, g_new);
    return out;
  }
  s.diagonal(diag);
  const Real alpha = residual_alpha(s, diag);
  // W: the diagonal, where it is positive.
  s.for_each(n, InverseDiagonal{diag.data(), inverse.data()});
  // r = the gradient at gamma = 0; N x = gradient(x) - r.
  s.for_each(n, Zero{probe.data()});
  s.gradient(probe, r);
  // f(x) = 1/2 x^T (N x) + r^T x = 1/2 x^T (g(x) + r).
  auto objective = [&](const Vector<Space>& x, const Vector<Space>& g) {
    return 0.5 * s.sum_of(n, ObjectiveTerm{x.data(), g.data(), r.data()});
  };
  // The Lipschitz constant of W^-1/2 N W^-1/2, estimated along W^-1/2 1 (a lower bound of
  // the largest eigenvalue; the backtracking raises it where it falls short).
  s.for_each(n, SquareRoot{inverse.data(), probe.data()});
  s.gradient(probe, g_new);
  Real lipschitz =
      std::sqrt(s.sum_of(n, ScaledProductSquare{g_new.data(), r.data(), inverse.data()}) / Real(n));
  if (!(lipschitz > 0)) lipschitz = 1;

  s.warm_start(gamma);
  s.project(gamma);
  s.copy(y, gamma);
  Real theta = 1;
  Real best_residual = std::numeric_limits<Real>::infinity();
  s.copy(best, gamma);
  for (out.iterations = 1; out.iterations <= settings.max_iterations; ++out.iterations) {
    s.gradient(y, g_y);
    const Real f_y = objective(y, g_y);
    for (;;) {
      const Real step = 1 / lipschitz;
      s.for_each(n, GradientStep{y.data(), inverse.data(), g_y.data(), step, gamma_new.data()});
      s.project(gamma_new);
      s.gradient(gamma_new, g_new);
      const Real f_new = objective(gamma_new, g_new);
      const Real model = f_y + s.sum_of(n, ModelTerm{g_y.data(), gamma_new.data(), y.data(),
                                                     diag.data(), lipschitz});
      // Round-off: a step that changes f by less than its last bits is accepted.
      if (f_new <= model + 1e-14 * std::abs(f_y) || lipschitz > 1e300) break;
      lipschitz *= 2;
    }
    const Real theta_new = 0.5 * (-theta * theta + theta * std::sqrt(theta * theta + 4));
    const Real beta = theta * (1 - theta) / (theta * theta + theta_new);
    const Real res = residual(s, gamma_new, g_new, alpha, scratch);
    if (res < best_residual) {
      best_residual = res;
      s.copy(best, gamma_new);
    }
    if (res < settings.tolerance) break;
    // An uphill step (the gradient at y against the step from gamma): restart the momentum.
    const Real uphill = s.sum_of(n, UphillTerm{g_y.data(), gamma_new.data(), gamma.data()});
    if (uphill > 0) {
      s.copy(y, gamma_new);
      theta = 1;
    } else {
      s.for_each(n, Momentum{gamma_new.data(), gamma.data(), beta, y.data()});
      theta = theta_new;
    }
    gamma.swap(gamma_new);
    lipschitz *= 0.9;
  }
  return finish(s, best, best_residual, out.iterations, settings, g_new);
}

// Projected Jacobi (projected_jacobi.cpp describes it).
template <class Space>
CcpResult projected_jacobi(Space& s, const CcpSettings& settings) {
  const std::size_t n = s.size();
  Vector<Space> gamma, g, diag, best, scratch;
  for (Vector<Space>* v : {&gamma, &g, &diag, &best, &scratch}) v->resize(n);
  CcpResult out;
  if (n == 0) {
    s.gradient(gamma, g);
    return out;
  }
  s.diagonal(diag);
  const Real alpha = residual_alpha(s, diag);
  s.for_each(n, ccp_steps::Zero{best.data()});  // what comes back if no residual is a number
  s.warm_start(gamma);
  s.project(gamma);
  Real best_residual = std::numeric_limits<Real>::infinity();
  for (out.iterations = 1; out.iterations <= settings.max_iterations; ++out.iterations) {
    s.gradient(gamma, g);
    const Real res = residual(s, gamma, g, alpha, scratch);
    if (res < best_residual) {
      best_residual = res;
      s.copy(best, gamma);
    }
    if (res < settings.tolerance) break;
    s.for_each(
        n, ccp_steps::JacobiStep{g.data(), diag.data(), settings.jacobi_relaxation, gamma.data()});
    s.project(gamma);
  }
  return finish(s, best, best_residual, out.iterations, settings, g);
}

}  // namespace sluice::ccp_iterations
