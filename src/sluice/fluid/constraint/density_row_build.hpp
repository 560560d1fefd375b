// Building one row of the density constraints (constraint_model.hpp says what a row counts) as a
// function of the row's index over plain arrays, so that the host builds its rows with it and a
// device can build its own (and which boundary particles get a row, NearFluid): the row's
// neighbours in the cells' order, its Jacobian entries, its parts on rigid bodies, its fluid
// neighbours' kernel values for the viscosity rows, its sigma, its constraint value and its
// density. What the row finds goes to a sink:
//   sink.entry(row, q)                a neighbour with a row of its own, and q_rk
//   sink.viscous(row, w)              a fluid row's fluid neighbour, and W
//   sink.body(body, linear, angular)  a part of the row's Jacobian on a rigid body (the sink
//                                     adds a body's parts together: one entry a body a row)
#pragma once

#include <cmath>
#include <cstdint>

#include "sluice/core/host_device.hpp"
#include "sluice/core/types.hpp"
#include "sluice/kernels/wendland_c2.hpp"
#include "sluice/neighbor/cell_list.hpp"
#include "sluice/particles/particle_set.hpp"

namespace sluice {

inline constexpr std::uint32_t kNoDensityRow = 0xFFFFFFFFu;

// 1 for a wall particle, or a body particle of its body's outer layer, with a fluid particle
// within the kernel's support (it gets a row), 0 otherwise. A body's deeper layers get no row:
// at the second layer's depth the fluid gives under 1 % of a particle's rest sum (0.7 % for
// the Wendland kernel at h = 1.3 dx), so a sampling error of a tenth of a percent in the
// body's own sum (a cylinder's rim, which no flat wall's share matches exactly) asked a fluid
// particle squeezed against the body for an eighth more room, and the row for a pressure of
// megapascals (B5's rolling wheels on the bed; docs/validation.md). The fluid's rows still
// count every layer, so the fluid stays out.
template <int D>
struct NearFluid {
  CellGridView<D> cells;
  const Vec<D>* position;
  const ParticleKind* kind;
  const std::int32_t* body_point;  // of every particle (-1: none)
  const char* outer_point;         // each body point: 1 in its body's outer layer
  Real support2;
  char* flag;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    flag[i] = 0;
    if (kind[i] == ParticleKind::kFluid) return;
    if (body_point[i] >= 0 && !outer_point[body_point[i]]) return;
    const Vec<D>& xi = position[i];
    cells.for_each_candidate_range(xi.data(), [&](std::uint32_t begin, std::uint32_t end) {
      for (std::uint32_t j = begin; j < end; ++j) {
        if (j == i || kind[j] != ParticleKind::kFluid) continue;
        if ((xi - position[j]).squaredNorm() < support2) flag[i] = 1;
      }
    });
  }
};

template <int D>
struct DensityRowInput {
  CellGridView<D> cells;            // the cells of the last sort
  const Vec<D>* position;           // of every particle
  const ParticleKind* kind;         // of every particle
  const std::int32_t* body_point;   // of every particle (-1: none)
  const std::uint32_t* point_body;  // each body point's body
  const Real* point_share;      // each body point's sum from its own wall in a flat lattice wall
  const Vec3* body_centre;      // each body's position
  const std::uint32_t* row_of;  // particle -> row (kNoDensityRow: none)
  const std::uint32_t* row_particle;  // row -> particle
  WendlandC2<D> kernel;
  Real mass, rest_sum, dx;
};

// What a row is besides its entries.
struct DensityRowValues {
  Vec3 sigma;  // the sum of its q
  Real c;      // dx (1 - rho / rho_ref)
  Real ratio;  // rho / rho_ref
};

template <int D, class Sink>
SLUICE_HOST_DEVICE DensityRowValues build_density_row(const DensityRowInput<D>& in, std::uint32_t r,
                                                      Sink& sink) {
  const std::size_t i = in.row_particle[r];
  const bool fluid = in.kind[i] == ParticleKind::kFluid;
  auto body_of = [&](std::size_t k) {
    return in.body_point[k] >= 0 ? std::int32_t(in.point_body[in.body_point[k]]) : -1;
  };
  const std::int32_t own_body = body_of(i);
  const Real scale = in.dx * in.mass / in.rest_sum;  // q = scale grad W
  const Real support = in.kernel.support();
  const Real support2 = support * support;
  Real sum = in.mass * in.kernel.value(0);
  Real own = fluid ? 0 : sum;  // a boundary row's part of the sum from its own solid
  Vec3 sigma = Vec3::Zero();
  const Vec<D>& xi = in.position[i];
  in.cells.for_each_candidate_range(xi.data(), [&](std::uint32_t begin, std::uint32_t end) {
    for (std::uint32_t j = begin; j < end; ++j) {
      const Vec<D> rij = xi - in.position[j];
      const Real r2 = rij.squaredNorm();
      if (!(r2 < support2) || j == i) continue;
      const bool j_fluid = in.kind[j] == ParticleKind::kFluid;
      const std::int32_t j_body = body_of(j);
      // Which neighbours a row counts: a fluid row, all; a wall row, the fluid and the
      // walls; a body row, the fluid and its own body (another solid pressing on it is a
      // contact of the rigid system, not a compression of the fluid).
      const bool counts = fluid || j_fluid || (own_body < 0 ? j_body < 0 : j_body == own_body);
      if (!counts) continue;
      const Real distance = std::sqrt(r2);
      const Real w = in.kernel.value(distance);
      sum += in.mass * w;
      if (!fluid && !j_fluid) own += in.mass * w;
      if (fluid && j_fluid) sink.viscous(in.row_of[j], w);
      if (!fluid && !j_fluid) continue;
      const Vec3 q = to_3d<D>(rij) * (scale * in.kernel.gradient_factor(distance));
      sigma += q;
      if (j_fluid || in.row_of[j] != kNoDensityRow) sink.entry(in.row_of[j], q);
      if (fluid && j_body >= 0) {
        const Vec3 arm = to_3d<D>(in.position[j]) - in.body_centre[j_body];
        sink.body(std::uint32_t(j_body), q, arm.cross(q));
      }
    }
  });
  if (own_body >= 0) {
    const Vec3 arm = to_3d<D>(in.position[i]) - in.body_centre[own_body];
    sink.body(std::uint32_t(own_body), -sigma, -arm.cross(sigma));
  }
  // A body row counts its own body no more than a particle at its depth in a flat lattice
  // wall counts its wall. Where a body is sampled closer than the lattice (a cylinder's rim,
  // a thin part's middle layer, a box's edges), the excess held the row over the rest
  // density with no fluid near: a constraint that no motion of the fluid can meet, and the
  // solve flung fluid particles at 70-90 m/s (the parked vehicle's 0.12 m wheels). The
  // body's part is fixed (it moves rigidly), so only the row's value changes, not its
  // Jacobian.
  if (own_body >= 0) {
    const Real excess = own - in.point_share[in.body_point[i]];
    sum -= excess > 0 ? excess : Real(0);
  }
  const Real ratio = sum / in.rest_sum;
  return {sigma, in.dx * (1 - ratio), ratio};
}

}  // namespace sluice
