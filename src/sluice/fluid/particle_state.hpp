// Everything a particle model evolves: the particles and their neighbour grid, with the case's
// constants they need.
#pragma once

#include <cstdint>
#include <vector>

#include "sluice/core/types.hpp"
#include "sluice/geometry/axis_box.hpp"
#include "sluice/neighbor/cell_list.hpp"
#include "sluice/particles/particle_set.hpp"

namespace sluice {

template <int D>
struct ParticleState {
  ParticleSet<D> particles;
  CellList<D> cells;
  Vec<D> gravity = Vec<D>::Zero();
  Real spacing = 0;
  Real kinematic_viscosity = 0;
  AxisBox domain;
  // The domain grown by the wall thickness: a fluid particle outside it has escaped.
  AxisBox escape_box;
  std::size_t fluid_count = 0;
  // Acceleration of each body point over the last step (BodyPoints order): moving walls feel
  // it in their pressure.
  std::vector<Vec3> body_point_acceleration;
};

}  // namespace sluice
