// Vector arithmetic of the CCP solvers over their unknowns, run by the execution policy; dot
// products sum in fixed blocks (exec::kSumBlock), so that the solvers take the same iterates
// on any number of threads.
#pragma once

#include <span>
#include <vector>

#include "sluice/core/types.hpp"
#include "sluice/exec/policy.hpp"

namespace sluice::ccp_vectors {

inline Real dot(std::span<const Real> a, std::span<const Real> b) {
  return exec::Default::sum_of(a.size(), [&](std::size_t i) { return a[i] * b[i]; });
}

// out = a + s b
inline void add_scaled(std::span<const Real> a, Real s, std::span<const Real> b,
                       std::vector<Real>& out) {
  out.resize(a.size());
  exec::Default::for_each_light(a.size(), [&](std::size_t i) { out[i] = a[i] + s * b[i]; });
}

// The largest effective mass's inverse: alpha of the residual is 1e-3 over it.
inline Real residual_alpha(std::span<const Real> diagonal) {
  const Real largest =
      exec::Default::max_of(diagonal.size(), [&](std::size_t i) { return diagonal[i]; });
  return largest > 0 ? 1e-3 / largest : 1e-3;
}

}  // namespace sluice::ccp_vectors
