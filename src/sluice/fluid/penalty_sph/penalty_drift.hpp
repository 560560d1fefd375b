// The drift of a penalty-sph step as loop bodies over plain arrays (as
// penalty_sph_loop_bodies.hpp's), run by the host's threads on its particle set and by a device
// run on its copy: each listed fluid particle moves through the solids by the stepper of
// solid_contact_stepper.hpp, its step's results add up per particle, and what it gave the
// bodies' particles is tallied per body point; then the end-of-step velocity and boundary force,
// the step's counters, and the penalty springs' energy.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "sluice/core/host_device.hpp"
#include "sluice/exec/bounded_list.hpp"
#include "sluice/fluid/penalty_sph/solid_contact_stepper.hpp"
#include "sluice/fluid/penalty_sph/solid_particles.hpp"

namespace sluice {

// What the drift reads and writes, one entry per particle.
template <int D>
struct PenaltyDriftArrays {
  Vec<D>* position = nullptr;
  Vec<D>* half_velocity = nullptr;
  const Real* mass = nullptr;
  const Real* density = nullptr;
  SolidStepResult<D>* results = nullptr;  // over the step so far
};

// The host's scratch for the drift: a growing candidate list per thread and, with bodies, a
// tally per listed particle (`tallies`, sized by the caller; null without bodies).
template <int D>
struct HostDriftScratch {
  using Entries = std::vector<BodyImpulse<D>>;
  std::vector<Entries>* tallies = nullptr;
  template <class Fn>
  void with(std::size_t n, Fn&& fn) const {
    thread_local std::vector<SolidCandidate> candidates;
    if (!tallies) return fn(candidates, static_cast<BodyImpulseTally<D, Entries>*>(nullptr));
    Entries& entries = (*tallies)[n];
    entries.clear();
    BodyImpulseTally<D, Entries> tally{entries};
    fn(candidates, &tally);
  }
};

// A device's scratch for the drift: lists of bounded length in the thread's own memory, and
// with bodies each listed particle's tally copied out to `records` (kTally entries a particle)
// with its length in `record_count`. A list too short voids the particle's step
// (SolidStepResult::overflowed), which the run turns into an error.
template <int D>
struct BoundedDriftScratch {
  // Solids within two supports of a fluid particle: about 130 in a corner of three walls of
  // one layer at the default 30 particles in the support; body points one particle touches in
  // one exchange: about 20.
  static constexpr int kCandidates = 512;
  static constexpr int kTally = 64;
  using Entries = BoundedList<BodyImpulse<D>, kTally>;
  BodyImpulse<D>* records = nullptr;  // null without bodies
  std::uint32_t* record_count = nullptr;
  template <class Fn>
  SLUICE_HOST_DEVICE void with(std::size_t n, Fn&& fn) const {
    BoundedList<SolidCandidate, kCandidates> candidates;
    if (!records) return fn(candidates, static_cast<BodyImpulseTally<D, Entries>*>(nullptr));
    Entries entries;
    BodyImpulseTally<D, Entries> tally{entries};
    fn(candidates, &tally);
    for (std::size_t e = 0; e < entries.size(); ++e) records[n * kTally + e] = entries[e];
    record_count[n] = static_cast<std::uint32_t>(entries.size());
  }
};

// Drifts fluid particle which[n] by dt through the solids, its fluid force's half kick in its
// velocity already (so the stepper holds none), and adds the drift to its step's results.
template <int D, class Scratch>
struct PenaltyDrift {
  PenaltyDriftArrays<D> a;
  SolidContactSettings<D> settings;
  SolidParticlesView<D> solids;
  const std::uint32_t* which;
  Real dt;
  Scratch scratch;
  SLUICE_HOST_DEVICE void operator()(std::size_t n) const {
    const std::size_t i = which[n];
    scratch.with(n, [&](auto& candidates, auto* tally) {
      const SolidStepResult<D> r =
          advance_against_solids<D>(settings, solids, a.position[i], a.half_velocity[i], a.mass[i],
                                    a.density[i], Vec<D>::Zero(), dt, candidates, tally);
      SolidStepResult<D>& total = a.results[i];
      total.impulse += r.impulse;
      total.peak_force = total.peak_force < r.peak_force ? r.peak_force : total.peak_force;
      total.substeps += r.substeps;
      total.touched = total.touched || r.touched;
      total.crossed = total.crossed || r.crossed;
      total.overflowed = total.overflowed || r.overflowed;
    });
  }
};

// Whether fluid particle i stays out of the bodies' reach over a step of dt, however fast
// either moves: the bodies' particles lie within [lo, hi] and move at most at body_speed.
template <int D>
struct PenaltyOutOfBodiesReach {
  const Vec<D>* position;
  const Vec<D>* half_velocity;
  const Vec<D>* acceleration;
  Vec<D> lo, hi;
  Real body_speed, support, dt;
  SLUICE_HOST_DEVICE bool operator()(std::size_t i) const {
    const Real travel =
        (half_velocity[i].norm() + body_speed) * dt + acceleration[i].norm() * dt * dt;
    const Real margin = 2 * support + 2 * travel;
    return ((position[i] - lo).array() < -margin).any() ||
           ((position[i] - hi).array() > margin).any();
  }
};

// The step's drift is done: the end-of-step velocity predicted for the viscosity, and the
// boundary force, the drift's impulse over the step.
template <int D>
struct PenaltyEndOfDrift {
  const std::int32_t* kind;
  const Vec<D>* half_velocity;
  const Vec<D>* acceleration;
  const SolidStepResult<D>* results;
  Vec<D>* velocity;
  Vec<D>* boundary_force;
  Real dt;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    if (kind[i] != 0) return;
    velocity[i] = half_velocity[i] + 0.5 * dt * acceleration[i];
    boundary_force[i] = results[i].impulse / dt;
  }
};

// A step's counters, each a sum (or a largest value) over the particles of one value each.
template <int D>
struct PenaltyStepCounters {
  const SolidStepResult<D>* results;
  const Vec<D>* boundary_force;
  struct Touched {
    const SolidStepResult<D>* r;
    SLUICE_HOST_DEVICE double operator()(std::size_t i) const { return r[i].touched ? 1 : 0; }
  };
  struct Crossed {
    const SolidStepResult<D>* r;
    SLUICE_HOST_DEVICE double operator()(std::size_t i) const { return r[i].crossed ? 1 : 0; }
  };
  struct Substeps {
    const SolidStepResult<D>* r;
    SLUICE_HOST_DEVICE double operator()(std::size_t i) const { return r[i].substeps; }
  };
  struct Overflowed {
    const SolidStepResult<D>* r;
    SLUICE_HOST_DEVICE double operator()(std::size_t i) const { return r[i].overflowed ? 1 : 0; }
  };
  // The boundary force of a particle in contact, and the largest force of its sub-steps.
  struct ContactForce {
    const SolidStepResult<D>* r;
    const Vec<D>* force;
    SLUICE_HOST_DEVICE double operator()(std::size_t i) const {
      return r[i].touched ? force[i].norm() : 0;
    }
  };
  struct PeakForce {
    const SolidStepResult<D>* r;
    SLUICE_HOST_DEVICE double operator()(std::size_t i) const {
      return r[i].touched ? r[i].peak_force : 0;
    }
  };
  // The step's counts and forces from these values, summed and maximised by `sum` and `max`
  // (each takes a value and returns its sum or largest over the particles).
  struct Totals {
    double touched = 0, crossed = 0, substeps = 0, contact_force = 0, peak_force = 0;
    bool overflowed = false;
  };
  template <class Sum, class Max>
  Totals totals(Sum&& sum, Max&& max) const {
    Totals t;
    t.touched = sum(touched());
    t.crossed = sum(crossed());
    t.substeps = sum(substeps());
    t.contact_force = sum(contact_force());
    t.peak_force = max(peak_force());
    t.overflowed = max(overflowed()) > 0;
    return t;
  }
  Touched touched() const { return {results}; }
  Crossed crossed() const { return {results}; }
  Substeps substeps() const { return {results}; }
  Overflowed overflowed() const { return {results}; }
  ContactForce contact_force() const { return {results, boundary_force}; }
  PeakForce peak_force() const { return {results}; }
};

// 1/2 Ks d^2 over fluid particle i's solids in contact now.
template <int D>
struct PenaltyElasticEnergy {
  const std::int32_t* kind;
  const Vec<D>* position;
  SolidParticlesView<D> solids;
  Real stiffness;
  SLUICE_HOST_DEVICE double operator()(std::size_t i) const {
    if (kind[i] != 0) return 0;
    double sum = 0;
    solids.for_each_near(position[i], [&](std::size_t k) {
      const Real d = solids.reach[k] - (position[i] - solids.position[k]).norm();
      if (d > 0) sum += 0.5 * stiffness * d * d;
    });
    return sum;
  }
};

}  // namespace sluice
