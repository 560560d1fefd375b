// Inlets and outlets for the particle models, as buffer zones (the buffers of Tafuni et al. 2018,
// CMAME 342, in DualSPHysics; Federico et al. 2012, Eur. J. Mech. B 34, for open channels): the
// first layers of the domain along an open side, as deep as the model's support, hold particles
// that the model sees as wall particles (their pressure is the fluid's, extrapolated) and the
// buffer moves itself.
// - Inlet: its particles move into the domain at the inflow's velocity; one that crosses the
//   buffer's inner face becomes fluid, and a copy of it one buffer's depth back takes its place,
//   so that the buffer stays full and the mass flux in is the buffer's, without a jump. Fluid
//   that drifts back into the buffer (beside a no-slip wall, where the inflow is slow) goes.
// - Outlet: fluid that enters the buffer becomes a buffer particle that moves at the velocity of
//   the fluid just inside the buffer's face at its place across the flow (a zero gradient along
//   the outward normal; its pressure prescribed, where the case gives a pressure or a depth,
//   else the fluid's); it goes when it leaves the domain, and becomes fluid again if it turns
//   back.
// A buffer particle's `open_boundary` field is its boundary's index plus one (0: none).
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "sluice/core/types.hpp"
#include "sluice/geometry/axis_box.hpp"
#include "sluice/io/boundary_config.hpp"
#include "sluice/particles/particle_set.hpp"

namespace sluice {

// What a pass handed over between the fluid and the buffers (indices into the particle set
// before the neighbour sort): the particles that became fluid (an inlet's that crossed into the
// domain, an outlet's that turned back), the fluid that entered an outlet's buffer, and the
// fluid that drifted back into an inlet's buffer, which goes (as in Tafuni et al.'s buffers: the
// inflow there is the buffer's alone).
struct BufferHandOver {
  std::vector<std::uint32_t> joined, left, dropped;
};

template <int D>
class ParticleOpenBoundaries {
 public:
  ParticleOpenBoundaries() = default;
  // `layers`: the buffers' depth in spacings; `up_gravity`: gravity along the vertical (negative
  // when down), for hydrostatic pressures below a depth measured from the domain's floor.
  ParticleOpenBoundaries(std::vector<io::BoundaryConfig> sides, const AxisBox& domain, Real spacing,
                         int layers, Real density, Real up_gravity);

  bool empty() const { return sides_.empty(); }
  std::size_t size() const { return sides_.size(); }

  // The inlets' buffers, as boxes to fill with particles (below each inlet's depth).
  std::vector<std::pair<std::size_t, AxisBox>> inlet_buffers() const;
  // Whether x lies in an inlet's buffer (where the fluid blocks put no particle of their own).
  bool in_inlet_buffer(const Vec<D>& x) const;
  // The inflow's velocity at x at `time` of inlet `index`.
  Vec<D> inflow_velocity(std::size_t index, const Vec<D>& x, double time) const;

  // Once the particles are built: the fluid found in an outlet's buffer joins it; returns how
  // many particles that was.
  std::size_t start(ParticleSet<D>& ps, FieldHandle<std::int32_t> zone) const;
  // After the drift of a step of `dt` from `time`: moves the buffers' particles on, hands the
  // particles across the buffers' inner faces over (fluid <-> buffer), fills the inlets' buffers
  // behind those that left them, and marks in `gone` (sized to the set) the outlets' particles
  // that left the domain; `hand_over` lists who changed sides (the model sets up its own state
  // of them). With `owned` (a field of the set: -1 for a ghost, another rank's particle or a
  // periodic image), the ghosts are left alone: their owners move them.
  void advance(ParticleSet<D>& ps, FieldHandle<std::int32_t> zone, double time, Real dt,
               std::vector<bool>& gone, BufferHandOver& hand_over,
               std::optional<FieldHandle<std::int32_t>> owned = std::nullopt) const;
  // After the model's boundary state: each outlet buffer particle's pressure, where the outlet
  // prescribes it, and the density `density_of(p)` of the model's equation of state. A model
  // whose free surface holds its pressure at the surface particles' centres (MPS) measures the
  // outlet's hydrostatic head from `surface_shift` (-dx/2) below its depth, where its own water's
  // pressure vanishes.
  template <class DensityOf>
  void prescribe_outlet_pressure(ParticleSet<D>& ps, FieldHandle<std::int32_t> zone,
                                 DensityOf&& density_of, Real surface_shift = 0) const {
    const auto& in = ps[zone];
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (in[i] == 0) continue;
      const io::BoundaryConfig& side = sides_[static_cast<std::size_t>(in[i] - 1)];
      if (side.kind != io::BoundaryKind::kOutlet || !prescribes_pressure(side)) continue;
      ps.pressure[i] = outlet_pressure(side, ps.position[i], surface_shift);
      ps.density[i] = density_of(ps.pressure[i]);
    }
  }

  // The volume flux out of the domain through the inner face of boundary `index`'s buffer
  // (inflow negative) [m^3/s; 2D: m^2/s]: the fluid's and the buffer's particles' volumes
  // (m / rho0) times their speed across the face, each spread over a spacing on either side of
  // it by a hat function (which sums to one over a lattice's rows). With `owned`, over the
  // particles this rank owns.
  double outflow(const ParticleSet<D>& ps, FieldHandle<std::int32_t> zone, std::size_t index,
                 std::optional<FieldHandle<std::int32_t>> owned = std::nullopt) const;

 private:
  // The side's axis in the model's coordinates (2D: x 0, z 1).
  static int model_axis(const io::BoundaryConfig& side) {
    return D == 3 ? side.axis : (side.axis == 0 ? 0 : 1);
  }
  // The coordinate along the side's axis of its buffer's inner face, and the sign of the
  // outward normal (+1 at an upper side).
  Real inner_face(const io::BoundaryConfig& side) const;
  static Real outward(const io::BoundaryConfig& side) { return side.upper ? 1 : -1; }
  // How far x lies beyond the buffer's inner face, outwards (negative: in the domain's interior).
  Real beyond_inner_face(const io::BoundaryConfig& side, const Vec<D>& x) const {
    return outward(side) * (x[model_axis(side)] - inner_face(side));
  }
  Real surface_of(const io::BoundaryConfig& side) const;
  // Fluid particle i, where it lies in an outlet's buffer, joins that buffer; whether it did.
  bool join_outlet(ParticleSet<D>& ps, FieldHandle<std::int32_t> zone, std::size_t i) const;
  bool prescribes_pressure(const io::BoundaryConfig& side) const {
    return side.pressure.has_value() || side.depth.has_value();
  }
  // The outlet's pressure at x: its pressure, and hydrostatic below its depth (shifted by
  // `surface_shift`).
  Real outlet_pressure(const io::BoundaryConfig& side, const Vec<D>& x, Real surface_shift) const;
  // Each of outlet `index`'s buffer particles takes the mean velocity of the fluid within two
  // spacings inside the buffer's face, in its square (strip, in 2D) two spacings wide across the
  // flow; one whose square holds no fluid keeps its velocity. With `owned`, the ghosts' velocities
  // count (they are copies) but are left to their owners to set.
  void extrapolate_outlet_velocity(ParticleSet<D>& ps, FieldHandle<std::int32_t> zone,
                                   std::size_t index,
                                   std::optional<FieldHandle<std::int32_t>> owned) const;

  std::vector<io::BoundaryConfig> sides_;
  AxisBox domain_;
  Real spacing_ = 0, buffer_depth_ = 0, density_ = 1000, up_gravity_ = 0;
};

}  // namespace sluice
