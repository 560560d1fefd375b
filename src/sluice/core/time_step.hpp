// A time step and what limits it, so that a step that collapses can say why ("the speed of
// sound", "the viscosity", ...). Each model starts from infinity and tightens it by each of its
// stability limits in turn.
#pragma once

#include <limits>

namespace sluice {

struct TimeStep {
  double dt = std::numeric_limits<double>::infinity();
  const char* limit = "nothing";  // a string literal naming the limiting quantity

  // Takes `candidate` when it is the smaller (a NaN candidate too: it names the culprit).
  void tighten(double candidate, const char* what) {
    if (candidate < dt || candidate != candidate) {
      dt = candidate;
      limit = what;
    }
  }
};

}  // namespace sluice
