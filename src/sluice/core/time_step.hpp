// A time step and what limits it, so that a step that collapses can say why ("the speed of
// sound", "the viscosity", ...). Each model starts from infinity and tightens it by each of its
// stability limits in turn.
#pragma once

#include <cmath>
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

// The step to take towards `until`, `remaining` ahead, where `stable` is the largest step the
// model allows: the whole of `remaining` in equal steps, none larger than `stable`. Taking
// `stable` and then what is left would alternate long and short steps between outputs (at
// 0.015 m in F3, 0.62 and 0.38 ms to every 1 ms probe), and an implicit MPS pressure answers a
// step size that alternates with a pressure that alternates: there, 0.18 m under the
// reservoir's surface (1.8 kPa hydrostatic), 2.7 kPa after each long step and next to nothing
// after each short one, where every probe read it (docs/validation.md, F3).
inline double step_towards(double remaining, double stable) {
  // Rounding must not add a step: `remaining` a hair over a whole number of `stable` steps
  // takes that number.
  const double steps = std::ceil(remaining / stable * (1 - 1e-9));
  return steps > 1 ? remaining / steps : remaining;
}

}  // namespace sluice
