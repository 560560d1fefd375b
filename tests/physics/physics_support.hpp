// Shared set-up for the physics checks: load a shipped case, run it in-process.
#pragma once

#include <omp.h>

#include <algorithm>

#include <string>
#include <utility>
#include <vector>

#include "sluice/fluid/fluid_view.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/sim/simulation.hpp"

namespace sluice::testing {

inline io::CaseConfig load_case(const std::string& name,
                                const std::vector<std::string>& overrides = {}) {
  return io::read_case(std::string(SLUICE_SOURCE_DIR) + "/cases/" + name, overrides);
}

// Runs until `end`, calling observe(clock) after every step.
template <int D, class Observe>
void run_until(Simulation<D>& sim, double end, Observe&& observe) {
  while (sim.time() < end * (1 - 1e-12)) {
    sim.step(end);
    observe(sim.clock());
  }
}

// The series v sampled at the increasing times t, read at `at`: linear between samples, held
// at the ends.
inline double interpolate(const std::vector<double>& t, const std::vector<double>& v, double at) {
  if (at <= t.front()) return v.front();
  if (at >= t.back()) return v.back();
  const auto k = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), at) - t.begin());
  return v[k - 1] + (at - t[k - 1]) / (t[k] - t[k - 1]) * (v[k] - v[k - 1]);
}

// Runs until `end` and returns the time mean, over (from, end], of the volume flux into the
// domain through open boundary `boundary` (its flux probe's reading at each step).
template <int D>
double mean_inflow(Simulation<D>& sim, std::size_t boundary, double from, double end) {
  const FluidObservation& fluid = sim.fluid().observation();
  double in = 0, span = 0;
  run_until(sim, end, [&](const StepClock& c) {
    if (c.time <= from) return;
    in -= c.dt * fluid.boundary_flux(boundary);
    span += c.dt;
  });
  return in / span;
}

// A field of a fluid's view (its points', or its cells') by name; null where it has none.
inline const FieldView* field_named(const std::vector<FieldView>& fields, const std::string& name) {
  for (const FieldView& field : fields)
    if (field.name() == name) return &field;
  return nullptr;
}

// What `run()` returns on one OpenMP thread and then on two (the thread count restored), for
// the checks that a model gives the same answer bit for bit on any number of threads.
template <class Run>
auto on_one_and_two_threads(Run&& run) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(1);
  auto one = run();
  omp_set_num_threads(2);
  auto two = run();
  omp_set_num_threads(before);
  return std::make_pair(std::move(one), std::move(two));
}

// F2: the 2D dam break's surge front (cases/dam_break_2d.yaml with `overrides`) against
// Koshizuka & Oka's (1996) over t in [0, 0.70] s: (a) the RMS difference as measured [m], and
// (b) the RMS with the experiment's clock started `delay` later, the delay in [0, 0.08] s (1 ms
// steps) that fits best (no model lifts the experiment's gate).
struct DamBreakFront {
  double rms = 0, delayed_rms = 0, delay = 0;
};
DamBreakFront dam_break_front(const std::vector<std::string>& overrides);
inline double dam_break_front_rms(const std::vector<std::string>& overrides) {
  return dam_break_front(overrides).rms;
}

// B1: the floating box's mean draft [m] over the last `averaged_over` seconds of
// cases/floating_box_2d.yaml (with `overrides`), how far it drifted sideways [m]: its mean
// sideways offset from where it started over the same span, and its largest sideways excursion
// [m] over that span. (The drift is the mean, not the largest excursion: with no sideways
// restoring force the box sways with the sloshing, and the largest excursion of one model's runs
// that differ only in the times their steps land on spans 2-9 mm, where the mean offset spans
// 0.4-2.7 mm; `constraint`, docs/validation.md, B1.)
struct FloatingBoxDraft {
  double draft = 0, drift = 0, excursion = 0;
};
FloatingBoxDraft floating_box_draft(const std::vector<std::string>& overrides,
                                    double averaged_over = 4.0);

}  // namespace sluice::testing
