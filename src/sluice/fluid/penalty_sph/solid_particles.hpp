// The solid particles a fluid particle of the penalty-sph model meets (walls, the case's solid
// layers, bodies), copied out of the particle set once per step into compact arrays sorted on a
// grid of their own. That grid's cells are two contact supports wide: a fluid particle collects
// the solids within two supports of where it stands once, and the list serves every sub-step
// while it stays within one support of that place (solid_contact_stepper.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "sluice/neighbor/cell_list.hpp"
#include "sluice/particles/particle_set.hpp"

namespace sluice {

template <int D>
struct SolidParticles {
  std::vector<Vec<D>> position;
  std::vector<Vec<D>> velocity;
  std::vector<Real> reach;   // where a fluid particle starts to touch: (L_b + l0) / 2 [m]
  std::vector<Real> volume;  // L_b^D, for the no-slip traction
  std::vector<std::int32_t> body_point;  // a body's particle: its body point; else -1
  CellList<D> grid;
  Real support = 0;  // the contact support S: no solid acts on a fluid particle beyond it

  bool empty() const { return position.empty(); }

  // Every non-fluid particle of `particles`, with its spacing from `spacing` (L_b), for fluid
  // particles of spacing `fluid_spacing`; `min_support` (the viscosity kernel's h) bounds S
  // from below.
  void gather(const ParticleSet<D>& particles, const std::vector<Real>& spacing, Real fluid_spacing,
              Real min_support) {
    std::vector<Vec<D>> x, v;
    std::vector<Real> b;
    std::vector<std::int32_t> points;
    Vec<D> lo = Vec<D>::Constant(1e300), hi = Vec<D>::Constant(-1e300);
    support = min_support;
    for (std::size_t i = 0; i < particles.size(); ++i) {
      if (particles.is_fluid(i)) continue;
      x.push_back(particles.position[i]);
      v.push_back(particles.velocity[i]);
      b.push_back(spacing[i]);
      points.push_back(particles.body_point[i]);
      lo = lo.cwiseMin(particles.position[i]);
      hi = hi.cwiseMax(particles.position[i]);
      support = std::max(support, (spacing[i] + fluid_spacing) / 2);
    }
    position.resize(x.size());
    velocity.resize(x.size());
    reach.resize(x.size());
    volume.resize(x.size());
    body_point.resize(x.size());
    if (x.empty()) return;
    grid = CellList<D>(lo, hi, 2 * support);
    std::vector<std::uint32_t> order;
    grid.sort(x, order);
    for (std::size_t k = 0; k < order.size(); ++k) {
      position[k] = x[order[k]];
      velocity[k] = v[order[k]];
      reach[k] = (b[order[k]] + fluid_spacing) / 2;
      volume[k] = std::pow(b[order[k]], D);
      body_point[k] = points[order[k]];
    }
  }

  // The solids within two supports of x, into `out` (cleared first).
  void near(const Vec<D>& x, std::vector<std::uint32_t>& out) const {
    out.clear();
    if (empty()) return;
    grid.for_each_near(position, x, 4 * support * support, [&](std::size_t k, const Vec<D>&, Real) {
      out.push_back(static_cast<std::uint32_t>(k));
    });
  }
};

}  // namespace sluice
