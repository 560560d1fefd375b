// The host as the space the complementarity solvers run in (ccp_iterations.hpp): the problem's
// groups on the host, vectors of reals, loops on the execution policy (its light loops: a dozen
// short loops an iteration), sums in its fixed blocks.
#pragma once

#include <vector>

#include "sluice/ccp/ccp_problem.hpp"
#include "sluice/exec/policy.hpp"

namespace sluice {

struct HostCcpSpace {
  using Vector = std::vector<Real>;

  CcpProblem& problem;
  BodyVelocities& velocities;  // after the impulses of the last gradient

  std::size_t size() const { return problem.size(); }
  static void copy(Vector& to, const Vector& from) { to = from; }
  void gradient(const Vector& x, Vector& g) { problem.gradient(x, g, velocities); }
  void project(Vector& x) const { problem.project(x); }
  void diagonal(Vector& d) const { problem.diagonal(d); }
  void warm_start(Vector& x) const { problem.warm_start(x); }
  void store(const Vector& x) { problem.store(x); }

  template <class Body>
  static void for_each(std::size_t n, Body&& body) {
    exec::Default::for_each_light(n, body);
  }
  template <class Value>
  static double sum_of(std::size_t n, Value&& value) {
    return exec::Default::sum_of(n, value);
  }
  template <class Value>
  static double max_of(std::size_t n, Value&& value) {
    return exec::Default::max_of(n, value);
  }
};

}  // namespace sluice
