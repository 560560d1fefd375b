#include "sluice/sim/particle_builder.hpp"

#include <fmt/format.h>

#include <cmath>

#include "sluice/geometry/sampling.hpp"

namespace sluice {

namespace {

template <int D>
std::vector<Vec<D>> sample_walls(const io::CaseConfig& config, int layers) {
  std::vector<Vec<D>> walls;
  for (const auto& wall : config.walls) {
    std::vector<Vec<D>> points;
    switch (wall.shape) {
      case io::WallShape::kTank:
        points = sample_tank_walls<D>(wall.box, wall.open_sides, config.spacing, layers);
        break;
      case io::WallShape::kBox:
        points = sample_solid_box<D>(wall.box, config.spacing, layers);
        break;
      case io::WallShape::kPlane:
        points =
            sample_plane_layers<D>(wall.point, wall.normal, config.domain, config.spacing, layers);
        break;
    }
    walls.insert(walls.end(), points.begin(), points.end());
  }
  return walls;
}

}  // namespace

template <int D>
ParticleState<D> build_state(const io::CaseConfig& config, Real interaction_radius,
                             const RigidBodies& bodies) {
  ParticleState<D> s;
  const Real dx = config.spacing;
  s.spacing = dx;
  s.gravity = from_3d<D>(config.gravity);
  s.rest_density = config.fluid.density;
  s.kinematic_viscosity = config.fluid.kinematic_viscosity;
  s.domain = config.domain;
  s.escape_box = config.domain;
  s.escape_box.min.array() -= interaction_radius;
  s.escape_box.max.array() += interaction_radius;
  const Real particle_volume = std::pow(dx, D);
  const Real mass = config.fluid.density * particle_volume;

  // Without fluid, walls are contact bodies only (RigidBodies): no wall particles.
  const std::vector<Vec<D>> walls =
      config.has_fluid() ? sample_walls<D>(config, wall_layers(interaction_radius, dx))
                         : std::vector<Vec<D>>{};

  // A grid over the walls and the domain, used first to drop fluid points that fall inside
  // walls, then as the simulation's neighbour grid.
  Vec<D> lo = from_3d<D>(config.domain.min), hi = from_3d<D>(config.domain.max);
  for (const auto& w : walls) {
    lo = lo.cwiseMin(w);
    hi = hi.cwiseMax(w);
  }
  CellList<D> wall_grid(lo, hi, dx);
  std::vector<std::uint32_t> order;
  std::vector<Vec<D>> sorted_walls = walls;
  wall_grid.sort(walls, order);
  for (std::size_t k = 0; k < order.size(); ++k) sorted_walls[k] = walls[order[k]];

  const Real up_gravity = s.gravity[kUpAxis<D>];  // negative when gravity points down
  const Real too_close2 = 0.81 * dx * dx;         // fluid closer than 0.9 dx to a wall is dropped
  for (const auto& block : config.fluid.blocks) {
    const Real top = block.box.max[2];
    const Vec<D> velocity = from_3d<D>(block.velocity);
    for (const Vec<D>& x : sample_box_volume<D>(block.box, dx)) {
      bool inside_wall = false;
      wall_grid.for_each_near(sorted_walls, x, too_close2,
                              [&](std::size_t, const Vec<D>&, Real) { inside_wall = true; });
      // A body's particles sit dx/2 under its surface; fluid closer than 0.4 dx to the
      // surface would be closer than 0.9 dx to them.
      if (inside_wall || bodies.occupies(to_3d<D>(x), 0.4 * dx)) continue;
      s.particles.add(x, velocity, config.fluid.density, mass, ParticleKind::kFluid);
      // Hydrostatic pressure below the block's top; the model turns it into density.
      s.particles.pressure.back() = config.fluid.density * up_gravity * (x[kUpAxis<D>] - top);
    }
  }
  s.fluid_count = s.particles.size();
  if (s.fluid_count == 0 && config.has_fluid()) {
    throw InputError(config.file(), config.fluid.blocks.front().line, "fluid.blocks",
                     "the fluid blocks yield no fluid particle (too small for the spacing, or "
                     "inside walls)");
  }
  for (const auto& w : walls) {
    s.particles.add(w, Vec<D>::Zero(), config.fluid.density, mass, ParticleKind::kWall);
  }
  for (std::size_t k = 0; k < bodies.points().size(); ++k) {
    const Vec<D> x = from_3d<D>(bodies.point_position(k));
    s.particles.add(x, from_3d<D>(bodies.point_velocity(k)), config.fluid.density, mass,
                    ParticleKind::kBody);
    s.particles.body_point.back() = static_cast<std::int32_t>(k);
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  s.body_point_acceleration.assign(bodies.points().size(), Vec3::Zero());

  s.cells = CellList<D>(lo, hi, interaction_radius);
  s.cells.sort(s.particles.position, order);
  s.particles.reorder(order);
  return s;
}

template ParticleState<2> build_state<2>(const io::CaseConfig&, Real, const RigidBodies&);
template ParticleState<3> build_state<3>(const io::CaseConfig&, Real, const RigidBodies&);

}  // namespace sluice
