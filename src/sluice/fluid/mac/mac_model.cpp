#include "sluice/fluid/mac/mac_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "sluice/core/errors.hpp"
#include "sluice/exec/policy.hpp"
#include "sluice/fluid/mac/advection.hpp"
#include "sluice/fluid/mac/level_set.hpp"
#include "sluice/fluid/mac/surface_mesh.hpp"
#include "sluice/fluid/mac/velocity_extension.hpp"
#include "sluice/fluid/mac/volume_correction.hpp"
#include "sluice/fluid/water_column.hpp"

namespace sluice {

namespace {

// How far into the air [cells] the velocity is extended each step.
constexpr Real kExtensionBand = 5;

// The nearest a solid's surface is taken to a face in the viscous term's no-slip condition, as
// a share of the spacing: nearer, the face all but takes the solid's velocity, and its load
// stays finite.
constexpr Real kSmallestWallTheta = 0.05;

std::vector<AxisBox> block_boxes(const io::CaseConfig& config) {
  std::vector<AxisBox> out;
  for (const auto& b : config.fluid.blocks) out.push_back(b.box);
  return out;
}

}  // namespace

template <int D>
MacModel<D>::MacModel(const MacParameters& parameters, const io::CaseConfig& config,
                      const BodyGeometry& bodies)
    : p_(parameters),
      grid_(mac_grid_of<D>(config, parameters)),
      solver_(mac_pressure_solver(parameters.solver, grid_.cell_count())),
      gravity_(from_3d<D>(config.gravity)),
      density_(config.fluid.density),
      viscosity_(config.fluid.kinematic_viscosity),
      geometry_(bodies),
      solid_(grid_, bodies,
             OpenBoundaries<D>(grid_, config.boundaries, config.fluid.density, -gravity_[D - 1],
                               config.domain.min[2])),
      projection_(make_sparse_solver(
          solver_, {parameters.tolerance, parameters.max_iterations, parameters.hypre})),
      surface_(grid_, level_set_of_blocks<D>(grid_, block_boxes(config), config.domain),
               parameters.particles_per_cell, parameters.reinitialise_every),
      motion_(bodies.motion()),
      loads_(bodies.body_count()),
      viscous_loads_(bodies.body_count()) {
  for (const io::BoundaryConfig& b : config.boundaries) {
    // An open channel 4 m long with its inflow ramped up over 3 s (20 s) broke up at 28 s
    // (34 s): the velocity of its surface layer grew, with either advection scheme.
    if (b.depth) {
      throw InputError(config.file(), b.line, b.key + ".depth",
                       "the mac model's open boundaries are for a channel full of water: a "
                       "free-surface channel (depth) is not stable yet");
    }
  }
  for (const auto& b : config.fluid.blocks) {
    if (b.velocity.norm() > 0) {
      throw InputError(config.file(), b.line, "fluid.blocks", "the mac model starts from rest");
    }
  }
  now_.u = make_face_field(grid_);
  if (!config.damping.empty()) {
    for (int a = 0; a < D; ++a) {
      const Lattice<D> faces = grid_.face_lattice(a);
      damping_rate_[a].assign(faces.size(), 0);
      for (std::size_t f = 0; f < faces.size(); ++f) {
        const Vec<D> x = faces.position(faces.coordinates(f));
        for (const io::DampingZone& z : config.damping) {
          damping_rate_[a][f] += z.rate_at(x[D == 2 && z.axis == 2 ? 1 : z.axis]);
        }
      }
    }
  }
  now_.pressure.assign(grid_.cell_count(), 0);
  for (int a = 0; a < D; ++a) valid_[a].assign(now_.u[a].size(), 0);
  surface_.carry_through(solid_.solid_cells());
  held_volume_ = water_volume();
  fill_inflow();
  // The pressure of the water at rest: one projection of gravity over a unit step, the
  // velocity it leaves discarded.
  add_forces(1.0);
  project(1.0, false);
  now_.u = make_face_field(grid_);
  for (Wrench& load : viscous_loads_) load = Wrench{};  // of that unit step: none at rest
  remember_good(0);
}

template <int D>
std::string MacModel<D>::describe() const {
  std::string cells = std::to_string(grid_.cells[0]);
  for (int a = 1; a < D; ++a) cells += " x " + std::to_string(grid_.cells[a]);
  return fmt::format(
      "mac: {} cells of {} m, {} advection, pressure by {} (tolerance {:g}), {} marker "
      "particles per cell and sign, cfl {}{}",
      cells, grid_.h, p_.maccormack ? "MacCormack" : "semi-Lagrangian", solver_, p_.tolerance,
      p_.particles_per_cell, p_.cfl, p_.volume_correction ? ", volume kept" : "");
}

template <int D>
void MacModel<D>::append_stages(StageList&, StageList& after_bodies) {
  after_bodies.push_back(
      make_stage<const StepClock>("advect", [this](const StepClock& c) { advect(c.dt); }));
  after_bodies.push_back(
      make_stage<const StepClock>("forces", [this](const StepClock& c) { add_forces(c.dt); }));
  after_bodies.push_back(make_stage<const StepClock>("boundaries", [this](const StepClock& c) {
    solid_.at_time(c.time + c.dt);
    if (motion_.empty()) return;
    solid_.place_bodies(motion_);
    surface_.carry_through(solid_.solid_cells());
  }));
  after_bodies.push_back(
      make_stage<const StepClock>("projection", [this](const StepClock& c) { project(c.dt); }));
  after_bodies.push_back(
      make_stage<const StepClock>("extension", [this](const StepClock&) { extend(); }));
}

template <int D>
FaceField<D> MacModel<D>::flux_velocity() const {
  // On a face partly within a solid, the projection holds only the flux, open u + (1 - open)
  // u_solid: the velocity of the open part alone is all but free where little is open (F3's
  // obstacle: 11-18 m/s on faces a quarter open and less, where the water moved at 2-3 m/s),
  // and carried by the advection into the water beside it, it fed the flow energy until the
  // run diverged. The face's mean velocity, the flux over its area, is what the water carries
  // and is carried by: divergence-free as the projection left it. Walls only: on a moving
  // body's faces the mean sank a floating box deeper (F11 at 0.04 m: mean draft 0.113 m
  // against 0.107 m and the case's 0.1 m), and there the velocity is left as it is.
  FaceField<D> flux = now_.u;
  const SolidFaces<D>& solid = solid_.faces();
  for (int a = 0; a < D; ++a) {
    exec::Default::for_each_light(flux[a].size(), [&](std::size_t f) {
      const Real w = solid.open[a][f];
      const bool wall = solid.body[a].empty() || solid.body[a][f] < 0;
      if (w < 1 && w > 0 && wall) flux[a][f] = w * flux[a][f] + (1 - w) * solid.velocity[a][f];
    });
  }
  return flux;
}

template <int D>
void MacModel<D>::advect(double dt) {
  const FaceField<D> flux = flux_velocity();
  FaceField<D> advected;
  for (int a = 0; a < D; ++a) {
    const Lattice<D> faces = grid_.face_lattice(a);
    advected[a] = p_.maccormack ? advect_maccormack(faces, flux[a], grid_, flux, dt)
                                : advect_semi_lagrangian(faces, flux[a], grid_, flux, dt);
  }
  // The water the surface should hold after the step: a running total, not the volume
  // measured before it, which a moving body changes as it covers and uncovers cells (a measure
  // taken after each move kept what the body's front had covered: B5's vehicle lost a tenth of
  // the water in 2 s).
  if (p_.volume_correction) {
    held_volume_ += boundary_inflow<D>(grid_, flux, surface_.phi(), solid_.faces(), dt);
  }
  surface_.advance(flux, dt, solid_.faces());
  if (p_.volume_correction) {
    restored_ += surface_.keep_volume(solid_.solid_cells(), held_volume_);
  }
  now_.u = std::move(advected);
  fill_inflow();
}

template <int D>
void MacModel<D>::fill_inflow() {
  const OpenBoundaries<D>& open = solid_.open_boundaries();
  if (open.empty()) return;
  // The water an inlet's cells are set to is the case's to give: the surface holds it too.
  const double before = p_.volume_correction ? water_volume() : 0.0;
  surface_.edit_phi([&](CellField& phi) { open.fill_inflow(phi); });
  if (p_.volume_correction) held_volume_ += water_volume() - before;
  open.fill_inflow(now_.u);
}

template <int D>
void MacModel<D>::add_forces(double dt) {
  if (viscosity_ > 0) diffuse(dt);
  for (int a = 0; a < D; ++a) {
    if (gravity_[a] == 0) continue;
    for (Real& v : now_.u[a]) v += dt * gravity_[a];
  }
  // The damping zones' relaxation, exact over the step for any rate (before the projection,
  // which keeps the relaxed field divergence-free).
  for (int a = 0; a < D; ++a) {
    for (std::size_t f = 0; f < damping_rate_[a].size(); ++f) {
      now_.u[a][f] *= std::exp(-damping_rate_[a][f] * dt);
    }
  }
}

template <int D>
void MacModel<D>::diffuse(double dt) {
  // Beyond the grid's boundary the wall's surface velocity holds the fluid half a cell out (an
  // inlet's: none across it; an outlet lets it through, zero gradient). Inside the grid, a
  // neighbour within a solid is replaced by the solid's velocity where the segment to it
  // crosses the surface (the ghost-fluid Dirichlet condition of Gibou et al. 2002), taken
  // implicitly so that a surface close to a face keeps the step stable.
  const Real k = viscosity_ * dt / (grid_.h * grid_.h);
  const Lattice<D> nodes = grid_.node_lattice();
  const std::vector<Real>& node_distance = solid_.node_distance();
  const OpenBoundaries<D>& open = solid_.open_boundaries();
  struct Crossing {
    Real theta;     // of the way from the face to its neighbour
    Real velocity;  // the solid's there, this component
    int body;       // or -1: a wall
    Vec<D> at;
  };
  for (auto& load : viscous_loads_) load = Wrench{};
  for (int a = 0; a < D; ++a) {
    const Lattice<D> faces = grid_.face_lattice(a);
    const std::vector<Real>& u = now_.u[a];
    std::vector<Real> distance(u.size());
    exec::Default::for_each_light(u.size(), [&](std::size_t f) {
      distance[f] = nodes.sample(node_distance, faces.position(faces.coordinates(f)));
    });
    // The explicit sum over a face's neighbours in the fluid and beyond the grid, each solid
    // neighbour handed to `on_solid`.
    auto stencil = [&](std::size_t f, auto&& on_solid) {
      const GridIndex<D> c = faces.coordinates(f);
      Real sum = 0;
      for (int b = 0; b < D; ++b) {
        for (const int side : {-1, 1}) {
          GridIndex<D> n = c;
          n[b] += side;
          if (!faces.contains(n)) {
            if (b == a) continue;
            const io::BoundaryConfig* beyond = open.beyond(b, side > 0);
            if (beyond != nullptr && beyond->kind == io::BoundaryKind::kOutlet) continue;
            Vec<D> x = faces.position(c);
            x[b] += side * 0.5 * grid_.h;
            const Real wall = beyond != nullptr ? 0 : solid_.wall_velocity_at(x)[a];
            sum += 2 * (wall - u[f]);
            continue;
          }
          const std::size_t m = faces.index(n);
          if (distance[f] >= 1.5 * grid_.h || distance[m] >= 0) {
            sum += u[m] - u[f];
            continue;
          }
          Crossing cross;
          cross.theta = std::max(kSmallestWallTheta, distance[f] / (distance[f] - distance[m]));
          cross.at = faces.position(c);
          cross.at[b] += side * cross.theta * grid_.h;
          cross.body = solid_.faces().body[a][m];
          if (cross.body >= 0) {
            const BodyKinematics& body = motion_[static_cast<std::size_t>(cross.body)];
            const Vec3 r = to_3d<D>(cross.at) - body.position;
            cross.velocity = from_3d<D>(body.velocity + body.angular_velocity.cross(r))[a];
          } else {
            cross.velocity = solid_.wall_velocity_at(cross.at)[a];
          }
          on_solid(cross);
        }
      }
      return sum;
    };
    std::vector<Real> out(u.size());
    std::vector<char> beside_solid(u.size(), 0);
    exec::Default::for_each(u.size(), [&](std::size_t f) {
      if (distance[f] < 0) {  // within a solid: the projection sets it
        out[f] = u[f];
        return;
      }
      Real weight = 0, pull = 0;
      const Real sum = stencil(f, [&](const Crossing& cross) {
        weight += 1 / cross.theta;
        pull += cross.velocity / cross.theta;
      });
      out[f] = (u[f] + k * (sum + pull)) / (1 + k * weight);
      beside_solid[f] = weight > 0;
    });
    // The momentum the solids gave the water, in the faces' order: each body's viscous load.
    const Real face_mass = density_ * std::pow(grid_.h, D);
    for (std::size_t f = 0; f < u.size(); ++f) {
      if (!beside_solid[f]) continue;
      stencil(f, [&](const Crossing& cross) {
        if (cross.body < 0) return;
        Vec<D> force = Vec<D>::Zero();
        force[a] = face_mass * k * (out[f] - cross.velocity) / (cross.theta * dt);
        Wrench& load = viscous_loads_[static_cast<std::size_t>(cross.body)];
        const Vec3 f3 = to_3d<D>(force);
        load.force += f3;
        load.moment +=
            (to_3d<D>(cross.at) - motion_[static_cast<std::size_t>(cross.body)].position).cross(f3);
      });
    }
    now_.u[a] = std::move(out);
  }
}

template <int D>
void MacModel<D>::project(double dt, bool moving) {
  std::vector<ProjectedBody> bodies(motion_.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const BodyKinematics& m = motion_[b];
    bodies[b].centre = m.position;
    bodies[b].velocity.head<3>() = m.velocity;
    bodies[b].velocity.tail<3>() = m.angular_velocity;
    if (!moving || solves_body_velocities_) continue;
    const BodyMobility mobility = geometry_.mobility(b);
    bodies[b].mobility.topLeftCorner<3, 3>() = mobility.inverse_mass;
    bodies[b].mobility.bottomRightCorner<3, 3>() = mobility.inverse_inertia;
    // The bodies advanced over this step with the pressure's load of the last; the projection
    // puts this step's in its place.
    Vec6 last;
    last.head<3>() = loads_[b].force;
    last.tail<3>() = loads_[b].moment;
    bodies[b].velocity -= dt * bodies[b].mobility * last;
  }
  const bool joined = moving && solves_body_velocities_ && !bodies.empty();
  if (!joined) {
    last_projection_ = projection_.project(grid_, surface_.phi(), solid_.faces(), dt, density_,
                                           now_.u, now_.pressure, valid_, bodies);
  } else {
    // The bodies' contacts hold as joints through the solve; where the pressure it gives would
    // have a contact pull a body onto what it stands on (water squeezed under a wheel), that
    // contact lets go and the solve is made again from the same state.
    const Eigen::MatrixXd mobility = geometry_.joined_mobility();
    // The viscous stress's impulse over the step, through the same mobility.
    Eigen::VectorXd viscous(6 * static_cast<Eigen::Index>(bodies.size()));
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      viscous.segment<3>(6 * static_cast<Eigen::Index>(b)) = dt * viscous_loads_[b].force;
      viscous.segment<3>(6 * static_cast<Eigen::Index>(b) + 3) = dt * viscous_loads_[b].moment;
    }
    if (viscous.squaredNorm() > 0) {
      const Eigen::VectorXd change = mobility * viscous;
      for (std::size_t b = 0; b < bodies.size(); ++b)
        bodies[b].velocity += change.segment<6>(6 * static_cast<Eigen::Index>(b));
    }
    const FaceField<D> u = now_.u;
    const CellField pressure = now_.pressure;
    const FaceMarks<D> valid = valid_;
    const std::vector<ProjectedBody> before = bodies;
    last_projection_ = projection_.project(grid_, surface_.phi(), solid_.faces(), dt, density_,
                                           now_.u, now_.pressure, valid_, bodies, &mobility);
    Eigen::VectorXd impulse(6 * static_cast<Eigen::Index>(bodies.size()));
    for (std::size_t b = 0; b < bodies.size(); ++b)
      impulse.segment<6>(6 * static_cast<Eigen::Index>(b)) = dt * bodies[b].load;
    const Eigen::MatrixXd released = geometry_.joined_mobility(impulse);
    if (released != mobility) {
      now_.u = u;
      now_.pressure = pressure;
      valid_ = valid;
      bodies = before;
      last_projection_ = projection_.project(grid_, surface_.phi(), solid_.faces(), dt, density_,
                                             now_.u, now_.pressure, valid_, bodies, &released);
      releases_ += 1;
    }
  }
  solved_velocities_.clear();
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    loads_[b].force = bodies[b].load.head<3>();
    loads_[b].moment = bodies[b].load.tail<3>();
    if (joined) solved_velocities_.push_back(bodies[b].velocity);
  }
  projections_ += 1;
  pressure_iterations_ += last_projection_.iterations;
  if (!last_projection_.converged) unconverged_ += 1;
  // The pressure carried into the solid cells beside the water, linearly along each axis
  // where two water cells line up (exact for hydrostatic pressure), so that the bodies' surface
  // and the probes on a wall sample it.
  const Lattice<D> cells = grid_.cell_lattice();
  CellField carried = now_.pressure;
  exec::Default::for_each(cells.size(), [&](std::size_t k) {
    if (!solid_.cell_is_solid(k)) return;
    const GridIndex<D> c = cells.coordinates(k);
    Real sum = 0;
    int count = 0;
    for (int a = 0; a < D; ++a) {
      for (const int side : {-1, 1}) {
        GridIndex<D> n1 = c, n2 = c;
        n1[a] += side;
        n2[a] += 2 * side;
        if (!cells.contains(n1) || !is_water(cells.index(n1))) continue;
        const Real p1 = now_.pressure[cells.index(n1)];
        const bool line = cells.contains(n2) && is_water(cells.index(n2));
        sum += line ? 2 * p1 - now_.pressure[cells.index(n2)] : p1;
        ++count;
      }
    }
    if (count > 0) carried[k] = sum / count;
  });
  now_.pressure = std::move(carried);
}

template <int D>
void MacModel<D>::extend() {
  // Advection reaches at most cfl (<= 2) cells and its interpolation one more from the water.
  extend_velocity<D>(grid_, surface_.phi(), valid_, now_.u, kExtensionBand * grid_.h);
}

template <int D>
TimeStep MacModel<D>::next_time_step() const {
  Real fastest = 0;
  for (int a = 0; a < D; ++a) {
    fastest = std::max(fastest, exec::Default::max_of(now_.u[a].size(), [&](std::size_t f) {
                         return valid_[a][f] ? std::abs(now_.u[a][f]) : 0.0;
                       }));
  }
  // What gravity adds over a step, after Bridson's "Fluid Simulation for Computer Graphics".
  fastest += std::sqrt(5 * grid_.h * gravity_.norm());
  TimeStep step;
  if (fastest > 0) step.tighten(p_.cfl * grid_.h / fastest, "the flow speed and gravity");
  if (viscosity_ > 0) step.tighten(0.9 * grid_.h * grid_.h / (2 * D * viscosity_), "the viscosity");
  if (p_.max_time_step > 0) step.tighten(p_.max_time_step, "model.max_time_step");
  return step;
}

template <int D>
void MacModel<D>::receive_body_motion(const std::vector<BodyKinematics>& motion) {
  motion_ = motion;
}

template <int D>
std::vector<Wrench> MacModel<D>::body_loads(const std::vector<BodyKinematics>&) const {
  std::vector<Wrench> total = loads_;
  for (std::size_t b = 0; b < total.size(); ++b) {
    total[b].force += viscous_loads_[b].force;
    total[b].moment += viscous_loads_[b].moment;
  }
  return total;
}

template <int D>
double MacModel<D>::boundary_flux(std::size_t index) const {
  return solid_.open_boundaries().outflow(index, now_.u, surface_.phi());
}

template <int D>
double MacModel<D>::pressure_at(const Vec3& x) const {
  return grid_.cell_lattice().sample(now_.pressure, from_3d<D>(x), nullptr, nullptr, 0.5);
}

template <int D>
double MacModel<D>::water_height_at(const Vec3& gauge) const {
  // The top of the lowest water on the vertical through the gauge (water_column.hpp), phi
  // interpolated across the columns and its crossing linearly between the cell centres.
  const Lattice<D> cells = grid_.cell_lattice();
  const int up = D - 1;
  Vec<D> x = from_3d<D>(gauge);
  auto phi_at = [&](int k) {
    x[up] = cells.first[up] + k * grid_.h;
    return cells.sample(surface_.phi(), x);
  };
  const int n = grid_.cells[up];
  const std::ptrdiff_t top = top_of_lowest_water(
      static_cast<std::size_t>(n), [&](std::size_t k) { return phi_at(static_cast<int>(k)) < 0; });
  if (top < 0) return 0;
  const int k = static_cast<int>(top);
  if (k == n - 1) return n * grid_.h;
  const Real below = phi_at(k);
  const Real above = phi_at(k + 1);
  return (k + 0.5) * grid_.h + grid_.h * below / (below - above);
}

template <int D>
double MacModel<D>::surge_front(int axis3) const {
  const int axis = (D == 2 && axis3 == 0) ? 0 : axis3;
  const Lattice<D> cells = grid_.cell_lattice();
  return exec::Default::max_of(cells.size(), [&](std::size_t k) {
    if (!is_water(k)) return -1e300;
    GridIndex<D> c = cells.coordinates(k);
    const Real x = cells.position(c)[axis];
    c[axis] += 1;
    if (!cells.contains(c)) return x + 0.5 * grid_.h;
    const CellField& phi = surface_.phi();
    const Real beyond = phi[cells.index(c)];
    if (beyond < 0) return x;
    return x + grid_.h * phi[k] / (phi[k] - beyond);
  });
}

template <int D>
std::optional<std::string> MacModel<D>::check(const StepClock& clock) const {
  const Lattice<D> cells = grid_.cell_lattice();
  auto report = [&](const Vec<D>& x, const char* what) {
    const Vec3 p = to_3d<D>(x);
    return diverged_at(clock.step, clock.time) +
           fmt::format("the cell at ({:.4g}, {:.4g}, {:.4g}): {}", p[0], p[1], p[2], what);
  };
  for (std::size_t k = 0; k < cells.size(); ++k) {
    if (!std::isfinite(surface_.phi()[k]))
      return report(cells.position(cells.coordinates(k)), "level set not finite");
    if (!std::isfinite(now_.pressure[k]))
      return report(cells.position(cells.coordinates(k)), "pressure not finite");
  }
  for (int a = 0; a < D; ++a) {
    const Lattice<D> faces = grid_.face_lattice(a);
    for (std::size_t f = 0; f < faces.size(); ++f) {
      if (!std::isfinite(now_.u[a][f]))
        return report(faces.position(faces.coordinates(f)), "velocity not finite");
    }
  }
  return std::nullopt;
}

template <int D>
void MacModel<D>::remember_good(double time) {
  last_good_ = now_;
  last_good_.phi = surface_.phi();
  last_good_time_ = time;
}

template <int D>
FluidView MacModel<D>::view_of(const CellField& phi, const Fields& f) const {
  FluidView view;
  std::vector<double> surface;
  for (const Vec3& x : surface_mesh<D>(grid_, phi))
    for (int a = 0; a < 3; ++a) surface.push_back(x[a]);
  view.positions = FieldView::holding("position", 3, std::move(surface));
  view.points_per_cell = D;

  FluidView::Cells grid;
  const Vec3 origin = to_3d<D>(grid_.origin);
  for (int a = 0; a < 3; ++a) grid.origin[a] = origin[a];
  grid.count = {grid_.cells[0], D == 3 ? grid_.cells[1] : 1, grid_.cells[D - 1]};
  grid.spacing = grid_.h;
  const Lattice<D> cells = grid_.cell_lattice();
  const std::size_t n = cells.size();
  std::vector<double> solid, velocity;
  for (std::size_t k = 0; k < n; ++k) {
    solid.push_back(solid_.cell_is_solid(k) ? 1.0 : 0.0);
    const Vec<D> v = velocity_at(grid_, f.u, cells.position(cells.coordinates(k)));
    for (int a = 0; a < D; ++a) velocity.push_back(v[a]);
  }
  grid.fields = {FieldView::of("pressure", 1, f.pressure.data(), n),
                 FieldView::of("level_set", 1, phi.data(), n),
                 FieldView::holding("velocity", D, std::move(velocity)),
                 FieldView::holding("solid", 1, std::move(solid))};
  view.cells = std::move(grid);
  return view;
}

template <int D>
FluidSize MacModel<D>::size() const {
  FluidSize s;
  s.element_name = "cells";
  s.elements = grid_.cell_count();
  for (std::size_t k = 0; k < s.elements; ++k) {
    if (solid_.cell_is_solid(k)) {
      ++s.wall;
    } else if (surface_.phi()[k] < 0) {
      ++s.fluid;
    }
  }
  return s;
}

template <int D>
double MacModel<D>::water_volume() const {
  return water_volume_of(grid_, surface_.phi(), solid_.solid_cells());
}

template <int D>
FluidEnergy MacModel<D>::energy() const {
  const Lattice<D> cells = grid_.cell_lattice();
  const Real cell_mass = density_ * std::pow(grid_.h, D);
  FluidEnergy e;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    if (solid_.cell_is_solid(k)) continue;
    const Real m = cell_mass * water_fraction(surface_.phi()[k], grid_.h);
    if (m == 0) continue;
    const Vec<D> x = cells.position(cells.coordinates(k));
    e.kinetic += 0.5 * m * velocity_at(grid_, now_.u, x).squaredNorm();
    e.potential -= m * gravity_.dot(x);
    e.mass += m;
  }
  return e;
}

template <int D>
std::vector<std::pair<std::string, double>> MacModel<D>::counters() const {
  std::vector<std::pair<std::string, double>> out = {
      {"pressure solves", projections_},
      {"pressure iterations", pressure_iterations_},
      {"unconverged pressure solves", unconverged_},
      {"pressure solves made again without a contact", releases_},
      {"marker particles", static_cast<double>(surface_.marker_count())}};
  if (p_.volume_correction) {
    out.emplace_back(D == 3 ? "water volume restored [m^3]" : "water area restored [m^2]",
                     restored_);
  }
  return out;
}

template <int D>
void MacModel<D>::archive_state(StateArchive& a) {
  a(now_.u, now_.pressure, valid_, motion_, loads_, viscous_loads_);
  projection_.archive_state(a);
  surface_.archive_state(a);
  a(projections_, pressure_iterations_, unconverged_, releases_);
  if (p_.volume_correction) {  // (a checkpoint is of one version of the case: the same choice)
    a(restored_, held_volume_);
    surface_.archive_kept_volume(a);
  }
  // Not carry_through: that would move the surface, which the checkpoint holds as it was.
  if (a.reading() && !motion_.empty()) solid_.place_bodies(motion_);
}

template class MacModel<2>;
template class MacModel<3>;

}  // namespace sluice
