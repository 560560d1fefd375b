// Moves one fluid particle of the penalty-sph model through a step against the solid
// particles, the fluid's own force held (as the solids' sub-steps hold it in seed 000).
//
// Why: the penalty spring of a fluid particle (mass m) on a solid has the frequency
// sqrt(Ks / m): 7000 rad/s for seed 002's first model at Ks = 5e4 N/m, 10^5 rad/s for its third,
// against a fluid step of 0.01 s. Stepped with the fluid, the spring throws the particle out at
// hundreds of metres per second. Here each particle takes sub-steps of its own:
//  - away from every solid (none within two supports of where its list was made), in free
//    flight, in as few pieces as keep it within one support of that place;
//  - in reach of solids, by linearly implicit Euler on the penalty spring-dashpot and the
//    no-slip traction, (m I + tau C + tau^2 K) v' = (m I + tau C) v + tau f, with K and C the
//    stiffness and damping of the touching solids along their normals (C also holds the
//    no-slip drag), in sub-steps that move it at most a twentieth of the reach and are cut
//    to 0.2 / omega where a new contact would start within them. That resolves the impact,
//    which decides whether the particle gets through, and stays stable and cheap for a
//    particle resting on the solid however stiff the spring.
// A body's solid particles move at constant velocity through the drift (SolidParticles::at),
// so that the springs see them move, not jump.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "sluice/core/host_device.hpp"
#include "sluice/exec/bounded_list.hpp"
#include "sluice/fluid/penalty_sph/penalty_boundary.hpp"
#include "sluice/fluid/penalty_sph/solid_particles.hpp"
#include "sluice/kernels/muller_kernels.hpp"

namespace sluice {

// The time after which a particle at `speed` under `acceleration` may have moved `distance`:
// the root of speed t + acceleration t^2 / 2 = distance.
SLUICE_HOST_DEVICE inline Real time_to_move(Real distance, Real speed, Real acceleration) {
  return 2 * distance / (speed + std::sqrt(speed * speed + 2 * acceleration * distance));
}

// x of a x = b for a sub-step's symmetric positive definite D x D matrix: Eigen's Cholesky on
// the host (and on the emulated device, so that both give the same bits); on a GPU, where
// Eigen's decompositions do not run, its closed-form inverse of a small fixed-size matrix.
template <int D>
SLUICE_HOST_DEVICE inline Vec<D> solve_symmetric_positive(const Eigen::Matrix<Real, D, D>& a,
                                                          const Vec<D>& b) {
#if defined(__CUDA_ARCH__)
  return a.inverse() * b;
#else
  return a.llt().solve(b);
#endif
}

template <int D>
struct SolidContactSettings {
  PenaltyLaw law;
  Real wall_friction = 0;  // mu_w [Pa s] of the no-slip traction
  MullerKernels<D> kernels{1};
  // The largest move of one sub-step in reach of solids, as a fraction of the reach.
  Real travel = 0.05;
};

template <int D>
struct SolidStepResult {
  Vec<D> impulse = Vec<D>::Zero();  // of the boundary force f_np + f_ns over the step [N s]
  Real peak_force = 0;              // the largest boundary force of a sub-step [N]
  int substeps = 0;
  bool touched = false;     // in penalty contact at some sub-step
  bool crossed = false;     // went past a solid particle's centre within a sub-step
  bool overflowed = false;  // a bounded list (a device's) was too short: the step is void
};

// The impulse a fluid particle gave a body's solid particle (its body point) in a drift.
template <int D>
struct BodyImpulse {
  std::int32_t body_point = -1;
  Vec<D> impulse = Vec<D>::Zero();
};

// A solid particle within two supports of where the fluid particle's list was made, and
// whether it presses on it at the present sub-step.
struct SolidCandidate {
  std::uint32_t index = 0;
  bool active = false;
};

// The impulses one fluid particle gives the bodies' particles over a drift, an entry per body
// point in the order it first touched them, into `entries` (a std::vector on the host, a
// BoundedList on a device). Summed per particle first, so that a device can add the particles'
// entries up per body point in particle order, as the host does (penalty_sph_model.hpp).
template <int D, class List>
struct BodyImpulseTally {
  List& entries;
  // False where the list is full.
  SLUICE_HOST_DEVICE bool add(std::int32_t body_point, const Vec<D>& impulse) {
    for (std::size_t e = 0; e < entries.size(); ++e) {
      if (entries[e].body_point == body_point) {
        entries[e].impulse += impulse;
        return true;
      }
    }
    return append(entries, BodyImpulse<D>{body_point, impulse});
  }
};

// Advances x, v by dt for a fluid particle of mass m and density rho, whose fluid force per
// unit mass, gravity included, is `acceleration`. `candidates` is scratch (a std::vector of
// SolidCandidate, or a BoundedList of them). With `on_bodies` (a BodyImpulseTally), the
// impulses on bodies' particles go to it: minus each one's share of every sub-step's implicit
// force times its length, the reaction of what the fluid particle felt.
template <int D, class Candidates, class Tally = BodyImpulseTally<D, std::vector<BodyImpulse<D>>>>
SLUICE_HOST_DEVICE SLUICE_ONE_HOST_COPY SolidStepResult<D> advance_against_solids(
    const SolidContactSettings<D>& settings, const SolidParticlesView<D>& solids, Vec<D>& x,
    Vec<D>& v, Real m, Real rho, const Vec<D>& acceleration, Real dt, Candidates& candidates,
    Tally* on_bodies = nullptr) {
  using Mat = Eigen::Matrix<Real, D, D>;
  SolidStepResult<D> out;
  const Real support = solids.support;
  const Real h2 = settings.kernels.h2;
  const Real fluid_volume = m / rho;
  // One contact's frequency, and the sub-step that resolves its impact.
  const Real omega = std::sqrt(settings.law.stiffness / m);
  const Real shortest = 0.2 / omega;
  // The no-slip drag of solid k on the particle at x moving at v, at time t (0 beyond h).
  auto drag_of = [&](std::uint32_t k, const Vec<D>& x_now, Real t) {
    const Real r2 = (x_now - solids.at(k, t)).squaredNorm();
    if (r2 >= h2 || settings.wall_friction <= 0) return Real(0);
    // f_ns = -mu_w V_b lap W_visc (v - v_b), a force density, times the particle's volume.
    return settings.wall_friction * solids.volume[k] *
           settings.kernels.viscosity_laplacian(std::sqrt(r2)) * fluid_volume;
  };
  Vec<D> anchor = x, previous = x;
  bool listed = false;
  Real t = 0, t_previous = 0;
  while (t < dt * (1 - 1e-12)) {
    ++out.substeps;
    if (!listed || (x - anchor).squaredNorm() > support * support) {
      candidates.clear();
      solids.for_each_near(x, [&](std::size_t k) {
        out.overflowed =
            !append(candidates, SolidCandidate{static_cast<std::uint32_t>(k), false}) ||
            out.overflowed;
      });
      if (out.overflowed) return out;
      anchor = x;
      listed = true;
    }
    const Real remaining = dt - t;
    if (candidates.size() == 0) {
      // Free flight until the path may leave the support around the anchor.
      const Real room = support - (x - anchor).norm();
      const Real tau = std::min(remaining, time_to_move(room, v.norm(), acceleration.norm()));
      previous = x;
      t_previous = t;
      x += tau * v + 0.5 * tau * tau * acceleration;
      v += tau * acceleration;
      t += tau;
      // At the edge of the room, list again from here.
      if (tau < remaining) listed = false;
      continue;
    }
    // The forces at x and their derivatives; a candidate is active where it presses now.
    Vec<D> force = m * acceleration;
    Mat stiffness = Mat::Zero(), damping = Mat::Zero();
    Vec<D> stiffness_times_solid_velocity = Vec<D>::Zero();
    Vec<D> spring_force = Vec<D>::Zero();
    Real approach = 0;  // the fastest approach along a contact's normal
    Real nearest_reach = support;
    // Where the particle was at the last sub-step, seen from where solid k is now.
    auto previous_seen_by = [&](std::uint32_t k) {
      return Vec<D>(previous + (t - t_previous) * solids.velocity[k]);
    };
    bool any_body = false;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      SolidCandidate& candidate = candidates[c];
      const std::uint32_t k = candidate.index;
      candidate.active = false;
      any_body = any_body || solids.body_point[k] >= 0;
      const Vec<D>& vb = solids.velocity[k];
      const Vec<D> xb = solids.at(k, t);
      const Vec<D> rel = x - xb;
      const Real r2 = rel.squaredNorm();
      const Real drag = drag_of(k, x, t);
      if (drag > 0) {
        force -= drag * (v - vb);
        damping.diagonal().array() += drag;
      }
      nearest_reach = std::min(nearest_reach, solids.reach[k]);
      const Vec<D> previous_here = previous_seen_by(k);
      // Out of reach and still on the side it came from: no contact (most candidates).
      if (r2 >= solids.reach[k] * solids.reach[k] && rel.dot(previous_here - xb) >= 0) continue;
      const PenaltyContact<D> p =
          penalty_contact<D>(settings.law, x, previous_here, v, xb, vb, solids.reach[k]);
      if (p.depth <= 0) continue;
      candidate.active = true;
      out.touched = true;
      out.crossed = out.crossed || p.crossed;
      // The spring's stiffness stays in the implicit step even where the law gives no force
      // (the dashpot would pull): dropping it lets a slow particle sink unchecked for a long
      // sub-step and be thrown out by the depth it reached.
      const Mat nn = p.normal * p.normal.transpose();
      stiffness += settings.law.stiffness * nn;
      stiffness_times_solid_velocity += settings.law.stiffness * p.normal.dot(vb) * p.normal;
      approach = std::max(approach, -(v - vb).dot(p.normal));
      spring_force += settings.law.stiffness * p.depth * p.normal;
      if (p.force.squaredNorm() == 0) continue;  // the dashpot would pull
      force += p.force;
      damping += settings.law.damping * nn;
    }
    // A sub-step moves |v| tau + |f / m| tau^2 / 2 within the allowed travel: a particle
    // resting on the springs (f ~ 0, v ~ 0) takes the rest of the step at once...
    Real tau = std::min(remaining,
                        time_to_move(settings.travel * nearest_reach, v.norm(), force.norm() / m));
    // A particle pressing into the springs faster than it would creep at rest (the speed
    // |Ks d| / (m omega) of its springs' load) is in an impact: resolved in fifths of 1/omega.
    // Sliding along the solid is not.
    if (approach > 10 * spring_force.norm() / (m * omega)) tau = std::min(tau, shortest);
    const Mat inertia_of_v = m * Mat::Identity();
    Vec<D> v_new;
    for (;;) {
      const Mat inertia = inertia_of_v + tau * damping;
      // The springs shorten by tau (v' - v_b) . n over the sub-step.
      v_new = solve_symmetric_positive<D>(
          inertia + tau * tau * stiffness,
          inertia * v + tau * force + tau * tau * stiffness_times_solid_velocity);
      // ...unless it would start to press on another solid deeper than an impact resolved
      // in fifths of 1/omega does: a spring switched on late stores energy it never took.
      if (tau <= shortest) break;
      const Real allowed =
          std::max(0.2 * std::max(v.norm(), v_new.norm()) / omega, 1e-4 * nearest_reach);
      const Vec<D> x_new = x + tau * v_new;
      bool late = false;
      for (std::size_t c = 0; c < candidates.size() && !late; ++c) {
        const std::uint32_t k = candidates[c].index;
        if (candidates[c].active) continue;
        const Real inside = solids.reach[k] - allowed;  // closer than this: pressing too deep
        late = inside > 0 && (x_new - solids.at(k, t + tau)).squaredNorm() < inside * inside;
      }
      if (!late) break;
      tau = std::max(shortest, tau / 4);
    }
    const Vec<D> impulse = m * (v_new - v) - tau * m * acceleration;
    out.impulse += impulse;
    // Each body particle's share of the implicit step, f_c - tau K_c (v' - v_b) - C_c (v' - v)
    // (the drag's, then the contact's, as the loop above took them): the shares add up to the
    // impulse the fluid particle took, so momentum is kept.
    if (on_bodies && any_body) {
      for (std::size_t c = 0; c < candidates.size(); ++c) {
        const std::uint32_t k = candidates[c].index;
        const std::int32_t point = solids.body_point[k];
        if (point < 0) continue;
        const Vec<D>& vb = solids.velocity[k];
        const Real drag = drag_of(k, x, t);
        if (drag > 0) {
          const Vec<D> f = -drag * (v - vb) - drag * (v_new - v);
          out.overflowed = !on_bodies->add(point, -tau * f) || out.overflowed;
        }
        if (!candidates[c].active) continue;
        const PenaltyContact<D> p = penalty_contact<D>(settings.law, x, previous_seen_by(k), v,
                                                       solids.at(k, t), vb, solids.reach[k]);
        const Real damping_c = p.force.squaredNorm() == 0 ? 0 : settings.law.damping;
        const Vec<D> f = p.force - (tau * settings.law.stiffness * p.normal.dot(v_new - vb) +
                                    damping_c * p.normal.dot(v_new - v)) *
                                       p.normal;
        out.overflowed = !on_bodies->add(point, -tau * f) || out.overflowed;
      }
      if (out.overflowed) return out;
    }
    out.peak_force = std::max(out.peak_force, impulse.norm() / tau);
    previous = x;
    t_previous = t;
    x += tau * v_new;
    v = v_new;
    t += tau;
  }
  return out;
}

}  // namespace sluice
