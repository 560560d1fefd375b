// APGD (Mazhar, Heyn, Negrut & Tasora, ACM TOG 34(3), 2015, Algorithm 1): Nesterov's
// accelerated projected gradient on the CCP's quadratic program. Each iteration: the gradient
// at the extrapolated point y, a projected step of 1/L from it, the step halved (L doubled)
// until f falls below its quadratic model at y, the momentum update, a restart of the momentum
// when the step went uphill, and L relaxed by 0.9 for the next iteration. The best iterate
// (smallest residual) is returned. Two products with N an iteration.
// Unlike the paper, the iteration runs in the metric of N's diagonal W (each row's inverse
// effective mass; one value per cone, so projections are unchanged): steps are W^-1 g / L and
// the model's quadratic term is L |d|_W^2 / 2. A body a thousand times heavier than the
// spheres about it (a box floating on a granular pool) then does not slow every row down.
#include <cmath>
#include <limits>

#include "sluice/ccp/apgd_steps.hpp"
#include "sluice/ccp/ccp_solver.hpp"
#include "sluice/ccp/ccp_vectors.hpp"

namespace sluice {

CcpResult solve_apgd(CcpProblem& problem, const CcpSettings& settings, BodyVelocities& velocities) {
  using namespace ccp_vectors;
  const std::size_t n = problem.size();
  std::vector<Real> gamma(n), gamma_new(n), y(n), g_y(n), g_new(n), r(n), best(n), scratch, diag(n),
      inverse(n);
  CcpResult out;
  if (n == 0) {
    problem.gradient(gamma, g_new, velocities);
    return out;
  }
  problem.diagonal(diag);
  const Real alpha = residual_alpha(diag);
  // W: the diagonal, where it is positive.
  exec::Default::for_each_light(n, apgd::InverseDiagonal{diag.data(), inverse.data()});
  // r = the gradient at gamma = 0; N x = gradient(x) - r.
  std::vector<Real> zero(n, 0);
  problem.gradient(zero, r, velocities);
  // f(x) = 1/2 x^T (N x) + r^T x = 1/2 x^T (g(x) + r).
  auto objective = [&](const std::vector<Real>& x, const std::vector<Real>& g) {
    return 0.5 * exec::Default::sum_of(n, apgd::ObjectiveTerm{x.data(), g.data(), r.data()});
  };
  // The Lipschitz constant of W^-1/2 N W^-1/2, estimated along W^-1/2 1 (a lower bound of
  // the largest eigenvalue; the backtracking raises it where it falls short).
  std::vector<Real> probe(n);
  exec::Default::for_each_light(n, apgd::SquareRoot{inverse.data(), probe.data()});
  problem.gradient(probe, g_new, velocities);
  Real lipschitz = std::sqrt(
      exec::Default::sum_of(n, apgd::ScaledProductSquare{g_new.data(), r.data(), inverse.data()}) /
      Real(n));
  if (!(lipschitz > 0)) lipschitz = 1;

  problem.warm_start(gamma);
  problem.project(gamma);
  y = gamma;
  Real theta = 1;
  Real best_residual = std::numeric_limits<Real>::infinity();
  best = gamma;
  for (out.iterations = 1; out.iterations <= settings.max_iterations; ++out.iterations) {
    problem.gradient(y, g_y, velocities);
    const Real f_y = objective(y, g_y);
    for (;;) {
      const Real step = 1 / lipschitz;
      exec::Default::for_each_light(
          n, apgd::GradientStep{y.data(), inverse.data(), g_y.data(), step, gamma_new.data()});
      problem.project(gamma_new);
      problem.gradient(gamma_new, g_new, velocities);
      const Real f_new = objective(gamma_new, g_new);
      const Real model =
          f_y + exec::Default::sum_of(n, apgd::ModelTerm{g_y.data(), gamma_new.data(), y.data(),
                                                         diag.data(), lipschitz});
      // Round-off: a step that changes f by less than its last bits is accepted.
      if (f_new <= model + 1e-14 * std::abs(f_y) || lipschitz > 1e300) break;
      lipschitz *= 2;
    }
    const Real theta_new = 0.5 * (-theta * theta + theta * std::sqrt(theta * theta + 4));
    const Real beta = theta * (1 - theta) / (theta * theta + theta_new);
    const Real residual = problem.residual(gamma_new, g_new, alpha, scratch);
    if (residual < best_residual) {
      best_residual = residual;
      best = gamma_new;
    }
    if (residual < settings.tolerance) break;
    // An uphill step (the gradient at y against the step from gamma): restart the momentum.
    const Real uphill =
        exec::Default::sum_of(n, apgd::UphillTerm{g_y.data(), gamma_new.data(), gamma.data()});
    if (uphill > 0) {
      y = gamma_new;
      theta = 1;
    } else {
      exec::Default::for_each_light(n,
                                    apgd::Momentum{gamma_new.data(), gamma.data(), beta, y.data()});
      theta = theta_new;
    }
    gamma.swap(gamma_new);
    lipschitz *= 0.9;
  }
  return finish_ccp(problem, best, best_residual, out.iterations, settings, g_new, velocities);
}

}  // namespace sluice
