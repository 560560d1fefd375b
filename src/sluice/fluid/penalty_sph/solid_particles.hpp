// The solid particles a fluid particle of the penalty-sph model meets, copied out of the
// particle set into compact arrays sorted on grids of their own: the fixed ones (walls, the
// case's fixed solid layers) once, the bodies' ones for every drift, each moving at a constant
// velocity from where it was to where the bodies' advance put it. The grids' cells are two
// contact supports wide: a fluid particle collects the solids within two supports of where it
// stands once, and the list serves every sub-step while it stays within one support of that
// place (solid_contact_stepper.hpp). SolidParticlesView is what the stepper reads, over the
// host's arrays here or a device's copy (penalty_sph_device_run_impl.hpp).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "sluice/core/host_device.hpp"
#include "sluice/neighbor/cell_list.hpp"
#include "sluice/particles/particle_set.hpp"

namespace sluice {

// The solids over plain arrays: the fixed ones first, [0, fixed_count), then the bodies'.
template <int D>
struct SolidParticlesView {
  const Vec<D>* position = nullptr;  // at the start of the drift
  const Vec<D>* velocity = nullptr;  // fixed: zero; a body's: over the drift
  const Real* reach = nullptr;       // where a fluid particle starts to touch: (L_b + l0) / 2 [m]
  const Real* volume = nullptr;      // L_b^D, for the no-slip traction
  const std::int32_t* body_point = nullptr;  // a body's particle: its body point; else -1
  std::size_t fixed_count = 0, count = 0;
  CellGridView<D> fixed_grid, moving_grid;  // cells two supports wide
  Real support = 0;  // the contact support S: no solid acts on a fluid particle beyond it

  // Where solid k is at time t of the drift.
  SLUICE_HOST_DEVICE Vec<D> at(std::size_t k, Real t) const {
    return position[k] + t * velocity[k];
  }

  // fn(k) for each solid k within two supports of x: the fixed ones, then the bodies', each in
  // its grid's order.
  template <class Fn>
  SLUICE_HOST_DEVICE void for_each_near(const Vec<D>& x, Fn&& fn) const {
    const Real r2 = 4 * support * support;
    auto scan = [&](const CellGridView<D>& grid, std::size_t offset) {
      grid.for_each_candidate_range(x.data(), [&](std::uint32_t begin, std::uint32_t end) {
        for (std::size_t k = offset + begin; k < offset + end; ++k) {
          if ((x - position[k]).squaredNorm() < r2) fn(k);
        }
      });
    };
    if (fixed_count > 0) scan(fixed_grid, 0);
    if (count > fixed_count) scan(moving_grid, fixed_count);
  }
};

template <int D>
struct SolidParticles {
  std::vector<Vec<D>> position;  // SolidParticlesView's arrays
  std::vector<Vec<D>> velocity;
  std::vector<Real> reach;
  std::vector<Real> volume;
  std::vector<std::int32_t> body_point;
  std::size_t fixed_count = 0;
  CellList<D> fixed_grid, moving_grid;
  Real support = 0;

  bool empty() const { return position.empty(); }

  SolidParticlesView<D> view() const {
    SolidParticlesView<D> v;
    v.position = position.data();
    v.velocity = velocity.data();
    v.reach = reach.data();
    v.volume = volume.data();
    v.body_point = body_point.data();
    v.fixed_count = fixed_count;
    v.count = position.size();
    v.fixed_grid = fixed_grid.view();
    v.moving_grid = moving_grid.view();
    v.support = support;
    return v;
  }

  // Every non-fluid particle of `particles` that is not a body's, with its spacing from
  // `spacing` (L_b), for fluid particles of spacing `fluid_spacing`; `min_support` (the
  // viscosity kernel's h) bounds S from below, and so does every solid, bodies' included.
  void gather(const ParticleSet<D>& particles, const std::vector<Real>& spacing, Real fluid_spacing,
              Real min_support) {
    fluid_spacing_ = fluid_spacing;
    std::vector<std::uint32_t> fixed;
    support = min_support;
    for (std::size_t i = 0; i < particles.size(); ++i) {
      if (particles.is_fluid(i)) continue;
      support = std::max(support, (spacing[i] + fluid_spacing) / 2);
      if (particles.body_point[i] < 0) fixed.push_back(static_cast<std::uint32_t>(i));
    }
    clear();
    fixed_grid = sorted_grid(particles, spacing, fixed, nullptr, 0);
    fixed_count = position.size();
  }

  // The bodies' particles `bodies` (indices into `particles`) for a drift of dt: each moves from
  // start[its body point] to where it is now, and start is then set to that place. With
  // dt = 0 they stand where they are.
  void gather_moving(const ParticleSet<D>& particles, const std::vector<Real>& spacing,
                     const std::vector<std::uint32_t>& bodies, std::vector<Vec<D>>& start,
                     Real dt) {
    position.resize(fixed_count);
    velocity.resize(fixed_count);
    reach.resize(fixed_count);
    volume.resize(fixed_count);
    body_point.resize(fixed_count);
    moving_grid = sorted_grid(particles, spacing, bodies, &start, dt);
  }

  // The solids within two supports of x, into `out` (cleared first).
  void near(const Vec<D>& x, std::vector<std::uint32_t>& out) const {
    out.clear();
    view().for_each_near(x, [&](std::size_t k) { out.push_back(static_cast<std::uint32_t>(k)); });
  }

 private:
  void clear() {
    position.clear();
    velocity.clear();
    reach.clear();
    volume.clear();
    body_point.clear();
  }

  // Appends `which` particles sorted on a grid of cells two supports wide, and returns the grid;
  // with `start`, each moves from start[body point] over dt (see gather_moving).
  CellList<D> sorted_grid(const ParticleSet<D>& particles, const std::vector<Real>& spacing,
                          const std::vector<std::uint32_t>& which, std::vector<Vec<D>>* start,
                          Real dt) {
    if (which.empty()) return {};
    std::vector<Vec<D>> x(which.size());
    Vec<D> lo = Vec<D>::Constant(std::numeric_limits<Real>::max()), hi = -lo;
    for (std::size_t n = 0; n < which.size(); ++n) {
      const std::uint32_t i = which[n];
      x[n] = start ? (*start)[static_cast<std::size_t>(particles.body_point[i])]
                   : particles.position[i];
      lo = lo.cwiseMin(x[n]);
      hi = hi.cwiseMax(x[n]);
    }
    CellList<D> grid(lo, hi, 2 * support);
    std::vector<std::uint32_t> order;
    grid.sort(x, order);
    for (const std::uint32_t n : order) {
      const std::uint32_t i = which[n];
      const std::int32_t point = particles.body_point[i];
      position.push_back(x[n]);
      velocity.push_back(start && dt > 0 ? Vec<D>((particles.position[i] - x[n]) / dt)
                                         : Vec<D>::Zero());
      reach.push_back((spacing[i] + fluid_spacing_) / 2);
      volume.push_back(std::pow(spacing[i], D));
      body_point.push_back(point);
      if (start) (*start)[static_cast<std::size_t>(point)] = particles.position[i];
    }
    return grid;
  }

  Real fluid_spacing_ = 0;
};

}  // namespace sluice
