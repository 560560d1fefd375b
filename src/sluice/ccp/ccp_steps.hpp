// The complementarity solvers' vector steps (ccp_iterations.hpp) as loop bodies over plain
// arrays, each a function of one unknown's index, so that the host's threads run them on the
// solver's vectors and a device run on its copies: APGD's diagonal metric, Lipschitz probe,
// objective and quadratic model terms, projected step, restart test and momentum; projected
// Jacobi's step; the residual's trial point and gap; and the rows' compliance and sign
// constraint that groups of compliant or unilateral rows share.
#pragma once

#include <cmath>
#include <cstddef>

#include "sluice/core/host_device.hpp"
#include "sluice/core/types.hpp"

namespace sluice::ccp_steps {

// W^-1 from the diagonal W of N, where it is positive (1 elsewhere, and W set to 1 there).
struct InverseDiagonal {
  Real* diagonal;
  Real* inverse;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    inverse[i] = diagonal[i] > 0 ? 1 / diagonal[i] : 1;
    if (!(diagonal[i] > 0)) diagonal[i] = 1;
  }
};

// The probe W^-1/2 1 of the Lipschitz estimate.
struct SquareRoot {
  const Real* in;
  Real* out;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const { out[i] = std::sqrt(in[i]); }
};

// ((N x)_i W_ii^-1/2)^2, N x = g - r, for the Lipschitz estimate's norm.
struct ScaledProductSquare {
  const Real* g;
  const Real* r;
  const Real* inverse;
  SLUICE_HOST_DEVICE double operator()(std::size_t i) const {
    const Real v = (g[i] - r[i]) * std::sqrt(inverse[i]);
    return v * v;
  }
};

// x_i (g_i + r_i): f(x) = 1/2 x^T (N x) + r^T x = 1/2 sum of these.
struct ObjectiveTerm {
  const Real* x;
  const Real* g;
  const Real* r;
  SLUICE_HOST_DEVICE double operator()(std::size_t i) const { return x[i] * (g[i] + r[i]); }
};

// out = y - step W^-1 g (to be projected).
struct GradientStep {
  const Real* y;
  const Real* inverse;
  const Real* g;
  Real step;
  Real* out;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    out[i] = y[i] - step * inverse[i] * g[i];
  }
};

// g_y d + L W d^2 / 2, d = x - y: the quadratic model's terms beyond f(y).
struct ModelTerm {
  const Real* g_y;
  const Real* x;
  const Real* y;
  const Real* diagonal;
  Real lipschitz;
  SLUICE_HOST_DEVICE double operator()(std::size_t i) const {
    const Real d = x[i] - y[i];
    return g_y[i] * d + 0.5 * lipschitz * diagonal[i] * d * d;
  }
};

// g_y (x_new - x): positive sums mean the step went uphill.
struct UphillTerm {
  const Real* g_y;
  const Real* x_new;
  const Real* x;
  SLUICE_HOST_DEVICE double operator()(std::size_t i) const { return g_y[i] * (x_new[i] - x[i]); }
};

// y = x_new + beta (x_new - x).
struct Momentum {
  const Real* x_new;
  const Real* x;
  Real beta;
  Real* y;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    y[i] = x_new[i] + beta * (x_new[i] - x[i]);
  }
};

// The vector's elements themselves (for their largest).
struct Element {
  const Real* values;
  SLUICE_HOST_DEVICE double operator()(std::size_t i) const { return values[i]; }
};

// A vector of zeros.
struct Zero {
  Real* out;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const { out[i] = 0; }
};

// Projected Jacobi's step gamma -= omega g / W, where W is positive.
struct JacobiStep {
  const Real* g;
  const Real* diagonal;
  Real omega;
  Real* gamma;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    if (diagonal[i] > 0) gamma[i] -= omega * g[i] / diagonal[i];
  }
};

// out += E gamma for compliant rows: each its own compliance, or one for all.
struct AddCompliance {
  const Real* compliance;
  const Real* gamma;
  Real* out;
  SLUICE_HOST_DEVICE void operator()(std::size_t r) const { out[r] += compliance[r] * gamma[r]; }
};
struct AddUniformCompliance {
  Real compliance;
  const Real* gamma;
  Real* out;
  SLUICE_HOST_DEVICE void operator()(std::size_t r) const { out[r] += compliance * gamma[r]; }
};

// Unilateral rows: gamma >= 0 (as std::max(gamma, 0) takes it).
struct NotNegative {
  Real* gamma;
  SLUICE_HOST_DEVICE void operator()(std::size_t r) const {
    gamma[r] = gamma[r] < 0 ? Real(0) : gamma[r];
  }
};

// The residual's trial point gamma - alpha g (to be projected), and then |gamma - P(...)|.
struct ResidualTrial {
  const Real* gamma;
  const Real* g;
  Real alpha;
  Real* out;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const { out[i] = gamma[i] - alpha * g[i]; }
};
struct ResidualGap {
  const Real* gamma;
  const Real* projected;
  SLUICE_HOST_DEVICE double operator()(std::size_t i) const {
    return std::abs(gamma[i] - projected[i]);
  }
};

}  // namespace sluice::ccp_steps
