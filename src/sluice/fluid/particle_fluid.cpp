#include "sluice/fluid/particle_fluid.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "sluice/core/errors.hpp"
#include "sluice/exec/policy.hpp"
#include "sluice/geometry/sampling.hpp"
#include "sluice/parallel/rcb_partition.hpp"

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

template <int D>
FluidEnergyShare<D> energy_share(const ParticleSet<D>& ps, const std::int32_t* kinds,
                                 const Vec<D>& gravity) {
  static_assert(sizeof(Vec<D>) == D * sizeof(Real), "a vector is D reals in a row");
  auto reals = [](const auto& v) { return v.empty() ? nullptr : v.front().data(); };
  return FluidEnergyShare<D>::over(ps.mass.data(), reals(ps.position), reals(ps.velocity), kinds,
                                   gravity.data());
}

// The axis, of the domain's horizontal ones, along which it is longest: water spreads along it.
int longest_horizontal_axis(const AxisBox& domain, int dimension) {
  const Vec3 extent = domain.max - domain.min;
  return dimension == 3 && extent[1] > extent[0] ? 1 : 0;
}

}  // namespace

void refuse_device_with_open_water(const io::CaseConfig& config, bool on_device) {
  if (on_device && (!config.boundaries.empty() || !config.damping.empty() || config.periodic)) {
    throw InputError(config.file(), config.model_line, "model.device",
                     "open and periodic boundaries and damping zones run on the CPU for now "
                     "(device: cpu)");
  }
}

template <int D>
ParticleFluid<D>::ParticleFluid(const io::CaseConfig& config, Real interaction_radius,
                                const BodyGeometry& bodies, Walls wall_kind)
    : radius_(interaction_radius),
      // Within the walls' particle layers, a fluid particle is put back on their surface.
      wall_surfaces_(config.walls, D,
                     std::max(wall_layers(interaction_radius, config.spacing), 1) * config.spacing),
      body_points_(config.has_fluid() ? bodies.points_under_surface(std::max(
                                            wall_layers(interaction_radius, config.spacing), 1))
                                      : bodies.surface_points()),
      body_count_(bodies.body_count()),
      damping_(config.damping),
      rcb_(config.ranks.partition == "rcb") {
  if (rcb_ && !rcb_offered()) {
    const auto& [file, line] = config.ranks.partition_place;
    throw InputError(file, line, "ranks.partition",
                     "rcb is Zoltan's, which this build lacks (configure with "
                     "-DSLUICE_WITH_ZOLTAN=ON and libtrilinos-zoltan-dev); choose slabs");
  }
  for (std::size_t w = 0; w < config.walls.size(); ++w) {
    if (config.walls[w].surface_velocity.norm() > 0) {
      throw InputError(config.file(), config.walls[w].line,
                       "walls[" + std::to_string(w) + "].surface_velocity",
                       "a moving wall surface is honoured by the grid model (mac) alone");
    }
  }
  ParticleState<D>& s = state_;
  const Real dx = config.spacing;
  s.spacing = dx;
  s.gravity = from_3d<D>(config.gravity);
  s.kinematic_viscosity = config.fluid.kinematic_viscosity;
  s.domain = config.domain;
  s.escape_box = config.domain;
  s.escape_box.min.array() -= interaction_radius;
  s.escape_box.max.array() += interaction_radius;
  const Real particle_volume = std::pow(dx, D);
  const Real mass = config.fluid.density * particle_volume;

  // Without fluid, walls are contact bodies only (RigidBodies): no wall particles.
  std::vector<Vec<D>> walls = config.has_fluid()
                                  ? sample_walls<D>(config, wall_layers(interaction_radius, dx))
                                  : std::vector<Vec<D>>{};
  if (config.periodic) join_periodic_sides(config, walls);

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
  auto clear_of_solids = [&](const Vec<D>& x) {
    bool inside_wall = false;
    wall_grid.for_each_near(sorted_walls, x, too_close2,
                            [&](std::size_t, const Vec<D>&, Real) { inside_wall = true; });
    // A body's particles sit dx/2 under its surface; fluid closer than 0.4 dx to the
    // surface would be closer than 0.9 dx to them.
    return !inside_wall && !bodies.occupies(to_3d<D>(x), 0.4 * dx);
  };
  // Water at x, with hydrostatic pressure below `top`; the model turns it into density.
  auto add_water = [&](const Vec<D>& x, const Vec<D>& velocity, Real top, ParticleKind kind) {
    s.particles.add(x, velocity, config.fluid.density, mass, kind);
    s.particles.pressure.back() = config.fluid.density * up_gravity * (x[kUpAxis<D>] - top);
  };
  if (!config.boundaries.empty()) {
    for (const io::BoundaryConfig& b : config.boundaries) {
      const bool backwards =
          b.mean_speed < 0 || std::any_of(b.speed_table.begin(), b.speed_table.end(),
                                          [](const auto& row) { return row.second < 0; });
      if (b.kind == io::BoundaryKind::kInlet && backwards) {
        throw InputError(config.file(), b.line,
                         b.key + (b.speed_table.empty() ? ".mean_speed" : ".speed_table"),
                         "a particle model's inlet only takes water in: its speed must not be "
                         "negative");
      }
    }
    const int layers = std::max(wall_layers(interaction_radius, dx), 1);
    open_ = ParticleOpenBoundaries<D>(config.boundaries, config.domain, dx, layers,
                                      config.fluid.density, up_gravity);
    open_zone_ = s.particles.add_int_field({"open_boundary", "1", true});
  }
  for (const auto& block : config.fluid.blocks) {
    const Vec<D> velocity = from_3d<D>(block.velocity);
    for (const Vec<D>& x : sample_box_volume<D>(block.box, dx)) {
      // An inlet's buffer is filled on the buffer's own lattice below.
      if (open_.in_inlet_buffer(x) || !clear_of_solids(x)) continue;
      add_water(x, velocity, block.box.max[2], ParticleKind::kFluid);
    }
  }
  s.fluid_count = s.particles.size();
  if (s.fluid_count == 0 && config.has_fluid()) {
    throw InputError(config.file(), config.fluid.blocks.front().line, "fluid.blocks",
                     "the fluid blocks yield no fluid particle (too small for the spacing, or "
                     "inside walls)");
  }
  if (!open_.empty()) {
    for (const auto& [b, box] : open_.inlet_buffers()) {
      for (const Vec<D>& x : sample_box_volume<D>(box, dx)) {
        if (!clear_of_solids(x)) continue;
        add_water(x, open_.inflow_velocity(b, x, 0), box.max[2], ParticleKind::kWall);
        s.particles[open_zone_].back() = static_cast<std::int32_t>(b + 1);
      }
    }
    s.fluid_count -= open_.start(s.particles, open_zone_);
  }
  // With the walls' surfaces alone, the walls were sampled all the same: those points kept the
  // fluid out of the walls and spanned the neighbour grid.
  if (wall_kind == Walls::kParticleLayers) {
    for (const auto& w : walls) {
      s.particles.add(w, Vec<D>::Zero(), config.fluid.density, mass, ParticleKind::kWall);
    }
  }
  const std::vector<BodyKinematics> motion = bodies.motion();
  for (std::size_t k = 0; k < body_points_.size(); ++k) {
    const Vec<D> x = from_3d<D>(body_points_.position(k, motion));
    s.particles.add(x, from_3d<D>(body_points_.velocity(k, motion)), config.fluid.density, mass,
                    ParticleKind::kBody);
    s.particles.body_point.back() = static_cast<std::int32_t>(k);
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  s.body_point_acceleration.assign(body_points_.size(), Vec3::Zero());

  if (periodic_) {
    // The periodic images stand within two supports beyond either side.
    lo[periodic_->axis] = std::min(lo[periodic_->axis], periodic_->lo - 2 * interaction_radius);
    hi[periodic_->axis] = std::max(hi[periodic_->axis], periodic_->hi + 2 * interaction_radius);
  }
  s.cells = CellList<D>(lo, hi, interaction_radius);
  s.cells.sort(s.particles.position, order);
  s.particles.reorder(order);
  // On one rank too, so that a checkpoint has the same fields on any number of ranks (and
  // resumes on another number).
  owned_kind_ = s.particles.add_int_field({"owned_kind", "1", false});
}

template <int D>
void ParticleFluid<D>::join_periodic_sides(const io::CaseConfig& config,
                                           std::vector<Vec<D>>& walls) {
  const io::PeriodicAxis& p = *config.periodic;
  const int axis = D == 3 ? p.axis : 0;  // 2D: x alone is periodic
  const Real lo = config.domain.min[p.axis], hi = config.domain.max[p.axis];
  const Real cells = (hi - lo) / config.spacing;
  if (std::abs(cells - std::round(cells)) > 1e-6 * cells) {
    throw InputError(config.file(), p.line, p.key + ".axis",
                     fmt::format("the domain's length along {} ({} m) is not a whole number of "
                                 "spacings ({} m): the lattice must repeat across the sides",
                                 "xyz"[p.axis], hi - lo, config.spacing));
  }
  periodic_ = PeriodicSpan{axis, lo, hi};
  periodic_key_ = p.key;
  periodic_place_ = {config.file(), p.line};
  // A wall's particles past a side (a plane's, sampled beyond the domain) would stand on top
  // of the other side's images.
  std::erase_if(walls, [&](const Vec<D>& x) { return x[axis] < lo || x[axis] >= hi; });
}

template <int D>
void ParticleFluid<D>::append_stages(StageList& before_bodies, StageList& after_bodies) {
  const auto start = static_cast<std::ptrdiff_t>(after_bodies.size());
  model_stages(before_bodies, after_bodies);
  // The engine's own stage, ahead of the model's later ones: sort the particles by cell so
  // that neighbours sit close in memory.
  auto neighbours = make_stage<const StepClock>("neighbours", [this](const StepClock& clock) {
    pass_open_boundaries(clock);
    sort_by_cell();
  });
  after_bodies.insert(after_bodies.begin() + start, std::move(neighbours));
  if (!damping_.empty()) {
    after_bodies.push_back(
        make_stage<const StepClock>("damping", [this](const StepClock& clock) { damp(clock.dt); }));
  }
}

template <int D>
void ParticleFluid<D>::damp(Real dt) {
  if (device_) throw std::logic_error("damp: the particles live on a device");
  auto& ps = state_.particles;
  exec::Default::for_each(ps.size(), [&](std::size_t i) {
    if (!ps.is_fluid(i)) return;
    double rate = 0;
    for (const io::DampingZone& zone : damping_)
      rate += zone.rate_at(ps.position[i][D == 2 && zone.axis == 2 ? 1 : zone.axis]);
    if (rate > 0) ps.velocity[i] *= std::exp(-rate * dt);
  });
}

template <int D>
void ParticleFluid<D>::distribute(const Communicator& ranks, Real halo_depth) {
  if (device_) throw std::logic_error("distribute: the particles live on a device");
  ranks_ = ranks;
  if (!ranks.split() && !periodic_) return;
  if (periodic_ && !(periodic_->length() > 2 * halo_depth)) {
    throw InputError(periodic_place_.first, periodic_place_.second, periodic_key_ + ".axis",
                     fmt::format("the domain along a periodic axis ({} m) must be longer than "
                                 "twice the model's reach across a side ({} m)",
                                 periodic_->length(), 2 * halo_depth));
  }
  split_evenly(halo_depth);
}

template <int D>
void ParticleFluid<D>::split_evenly(Real halo_depth) {
  auto& ps = state_.particles;
  // The first regions share the work as the balance counts it.
  const BalancePolicy balance;
  Decomposition regions;
  if (rcb_) {
    // Every rank holds the whole case: each hands Zoltan every size()-th particle, so that it
    // sees each once.
    const auto rank = static_cast<std::size_t>(ranks_.rank());
    const auto ranks = static_cast<std::size_t>(ranks_.size());
    regions = ParticleExchange<D>::rcb_of(ranks_, ps, balance,
                                          [&](std::size_t i) { return i % ranks == rank; });
  } else {
    const int axis = longest_horizontal_axis(state_.domain, D);
    std::vector<double> coordinates(ps.size()), work(ps.size());
    for (std::size_t i = 0; i < ps.size(); ++i) {
      coordinates[i] = ps.position[i][axis];
      work[i] = balance.work(ps.is_fluid(i));
    }
    regions = Decomposition(balanced_slabs(coordinates, work, axis, ranks_.size()));
  }
  exchange_ = std::make_unique<ParticleExchange<D>>(ranks_, std::move(regions), halo_depth,
                                                    owned_kind_, balance);
  if (periodic_) exchange_->join_sides(*periodic_);
  exchange_->start(ps);
  const std::size_t before = ps.size();
  state_.cells.sort(ps.position, order_);
  ps.reorder(order_);
  exchange_->follow(order_, before);
}

template <int D>
void ParticleFluid<D>::begin_gathering(int written_ranks) {
  if (device_) throw std::logic_error("begin_gathering: the particles live on a device");
  written_ranks_ = written_ranks;
  gathered_pieces_ = 0;
  gathered_.emplace();
  gathered_->assign_fields(state_.particles, [](const FieldLabel&) { return false; });
}

template <int D>
void ParticleFluid<D>::gather_piece(StateArchive& a) {
  ParticleSet<D> piece;
  piece.assign_fields(state_.particles, [](const FieldLabel&) { return false; });
  a.section("particles");
  piece.archive_state(a);
  a(state_.body_point_acceleration);  // every rank's is the whole case's
  CellList<D> cells = state_.cells;   // the piece's, drawn anew
  cells.archive_state(a);
  if (written_ranks_ > 1) {
    a.section("ranks");
    ParticleExchange<D>::skip_archived_state(a);
  }
  a.section("model");
  gather_model(a, gathered_pieces_ == 0);
  std::vector<std::uint32_t> own;
  const auto& owned = piece[owned_kind_];
  for (std::size_t i = 0; i < piece.size(); ++i) {
    // A ghost's owned kind is -1 (another rank's particle, or a periodic image, which a
    // one-rank periodic run keeps too); on one rank without either it is never set, 0.
    if (owned[i] >= 0) own.push_back(static_cast<std::uint32_t>(i));
  }
  std::vector<unsigned char> bytes;
  piece.pack(own, bytes);
  gathered_->unpack_append(bytes.data(), own.size());
  ++gathered_pieces_;
}

template <int D>
void ParticleFluid<D>::end_gathering() {
  if (!gathered_ || gathered_pieces_ != written_ranks_)
    throw std::logic_error("end_gathering: not every piece was read");
  state_.particles = std::move(*gathered_);
  gathered_.reset();
  if (exchange_) {
    split_evenly(exchange_->depth());
  } else {
    state_.cells.sort(state_.particles.position, order_);
    state_.particles.reorder(order_);
  }
  redistributed();
}

template <int D>
void ParticleFluid<D>::gather_model(StateArchive&, bool) {
  throw std::logic_error("this model's checkpoints do not resume on another number of ranks");
}

template <int D>
std::string ParticleFluid<D>::decomposition() const {
  if (!ranks_.split()) return {};
  const Decomposition& regions = exchange_->regions();
  return fmt::format("{} ranks: {}, ghosts within {:.4g} m of a {}", ranks_.size(),
                     regions.describe(), exchange_->depth(), regions.is_slabs() ? "slab" : "box");
}

template <int D>
std::vector<std::pair<std::string, double>> ParticleFluid<D>::counters() const {
  if (!ranks_.split()) return {};
  const ExchangeTotals& t = exchange_->totals();
  const double exchanges = std::max<double>(t.exchanges, 1);
  return {{"ghosts_per_exchange", ranks_.max(t.ghosts / exchanges)},
          {"migrated_per_exchange", ranks_.max(t.migrated / exchanges)},
          {"wait_seconds", ranks_.max(t.wait_seconds)},
          {"migration_seconds", ranks_.max(t.migration_seconds)},
          {"halo_seconds", ranks_.max(t.halo_seconds)},
          {"balance_seconds", ranks_.max(t.balance_seconds)},
          {"balances", static_cast<double>(t.balances)}};
}

template <int D>
const std::int32_t* ParticleFluid<D>::counted_kinds() const {
  const auto& ps = state_.particles;
  return exchange_ ? ps[owned_kind_].data() : reinterpret_cast<const std::int32_t*>(ps.kind.data());
}

template <int D>
void ParticleFluid<D>::run_on_device(std::unique_ptr<ParticleDevice<D>> device) {
  device_ = std::move(device);
  device_->upload(state_.particles, state_.body_point_acceleration, state_.cells.cell_starts());
  host_current_ = false;
}

template <int D>
void ParticleFluid<D>::run_on_emulated_device() {
  auto device = std::make_unique<ParticleDeviceOn<D, exec::HostBackend>>(device_setup());
  ParticleDeviceRun<D, exec::HostBackend>* loops = &device->run();
  run_on_device(std::move(device));
  emulated_loops_ = loops;
}

template <int D>
void ParticleFluid<D>::refresh_host() const {
  if (!device_ || host_current_) return;
  auto& s = const_cast<ParticleState<D>&>(state_);
  device_->download(s.particles, s.body_point_acceleration);
  // In the device's order, with its cells (what the probes read): a stage after the sort may
  // have moved a particle out of its cell, and a sort here would reorder the host's set.
  std::vector<std::uint32_t> start;
  device_->download_cell_starts(start);
  s.cells.assign_cell_starts(std::move(start));
  host_current_ = true;
}

template <int D>
void ParticleFluid<D>::sort_by_cell() {
  if (device_) return on_device([&] { device_->sort_by_cell(); });
  keep_out_of_walls();
  // With open boundaries, those that left the domain by an outlet go; split (or periodic), the
  // ghosts of the last step and the particles sent away go too (the exchange's gone()).
  const std::vector<bool>* left_the_domain =
      open_gone_.size() == state_.particles.size() ? &open_gone_ : nullptr;
  if (exchange_) exchange_->exchange(state_.particles, left_the_domain);
  const std::size_t before = state_.particles.size();
  const std::vector<bool>* gone = exchange_ ? &exchange_->gone() : left_the_domain;
  state_.cells.sort(state_.particles.position, order_, gone);
  state_.particles.reorder(order_);
  open_gone_.clear();
  if (exchange_) exchange_->follow(order_, before);
}

template <int D>
void ParticleFluid<D>::pass_open_boundaries(const StepClock& clock) {
  if (open_.empty()) return;
  auto& ps = state_.particles;
  // Split (or periodic): the ghosts are their owners' to move, and a particle's owned kind
  // follows its kind across a buffer's face (a copy made behind an inlet took its original's).
  const auto owned = exchange_ ? std::optional(owned_kind_) : std::nullopt;
  open_.advance(ps, open_zone_, clock.time, clock.dt, open_gone_, hand_over_, owned);
  if (owned) {
    for (const auto* changed : {&hand_over_.joined, &hand_over_.left})
      for (const std::uint32_t i : *changed) ps[*owned][i] = static_cast<std::int32_t>(ps.kind[i]);
  }
  state_.fluid_count += hand_over_.joined.size();
  state_.fluid_count -= hand_over_.left.size() + hand_over_.dropped.size();
  handed_over(hand_over_);
}

template <int D>
void ParticleFluid<D>::keep_out_of_walls() {
  auto& ps = state_.particles;
  const WallSurfacesView walls = wall_surfaces_.view();
  Vec<D>* carried = carried_velocity_ ? ps[*carried_velocity_].data() : nullptr;
  exec::Default::for_each(ps.size(), [&](std::size_t i) {
    if (ps.is_fluid(i))
      keep_out_of_wall_solids<D>(walls, ps.position[i].data(), ps.velocity[i].data(),
                                 carried ? carried[i].data() : nullptr);
  });
}

template <int D>
ParticleDeviceSetup<D> ParticleFluid<D>::device_setup() const {
  const ParticleState<D>& s = state_;
  ParticleDeviceSetup<D> setup{s.cells.view(), s.cells.cell_count(), body_points_.size()};
  setup.cells.cell_start = nullptr;  // the device keeps its own
  setup.body_first = body_points_.first_of_each_body(body_count_);
  setup.walls = wall_surfaces_.view();
  for (std::size_t k = 0; k < body_points_.size(); ++k) {
    for (int a = 0; a < 3; ++a) setup.point_local.push_back(body_points_[k].local[a]);
  }
  for (int a = 0; a < D; ++a) {
    const int a3 = D == 3 ? a : 2 * a;
    setup.escape_min[a] = s.escape_box.min[a3];
    setup.escape_max[a] = s.escape_box.max[a3];
  }
  if (carried_velocity_) setup.carried_velocity = s.particles.label(*carried_velocity_).name;
  return setup;
}

template <int D>
void ParticleFluid<D>::receive_body_motion(const std::vector<BodyKinematics>& motion) {
  if (device_) return on_device([&] { device_->set_body_motion(pack_body_motion(motion)); });
  auto& ps = state_.particles;
  exec::Default::for_each(ps.size(), [&](std::size_t i) {
    const std::int32_t k = ps.body_point[i];
    if (k < 0) return;
    ps.position[i] = from_3d<D>(body_points_.position(k, motion));
    ps.velocity[i] = from_3d<D>(body_points_.velocity(k, motion));
    state_.body_point_acceleration[k] = body_points_.acceleration(k, motion);
  });
}

template <int D>
std::vector<Wrench> ParticleFluid<D>::body_loads(const std::vector<BodyKinematics>& motion) const {
  if (body_points_.size() == 0) return std::vector<Wrench>(body_count_);
  if (body_forces_read_particles()) refresh_host();  // a model's forces read the host's set
  std::vector<Vec3> force(body_points_.size(), Vec3::Zero());
  body_point_forces(motion, force);
  if (!exchange_) return body_points_.loads(force, motion, body_count_);
  // A point's owner alone counts its force (or each rank its share of it); then the bodies'
  // loads add up over the ranks.
  const auto& ps = state_.particles;
  const std::int32_t* kinds = counted_kinds();
  for (std::size_t i = 0; i < ps.size() && !body_point_forces_are_rank_shares(); ++i) {
    if (ps.body_point[i] >= 0 && kinds[i] < 0) force[ps.body_point[i]] = Vec3::Zero();
  }
  std::vector<Wrench> loads = body_points_.loads(force, motion, body_count_);
  std::vector<double> sums;
  for (const Wrench& w : loads)
    sums.insert(sums.end(),
                {w.force[0], w.force[1], w.force[2], w.moment[0], w.moment[1], w.moment[2]});
  ranks_.sum(sums);
  for (std::size_t b = 0; b < loads.size(); ++b) {
    loads[b].force = Vec3(sums[6 * b], sums[6 * b + 1], sums[6 * b + 2]);
    loads[b].moment = Vec3(sums[6 * b + 3], sums[6 * b + 4], sums[6 * b + 5]);
  }
  return loads;
}

template <int D>
FluidSize ParticleFluid<D>::size() const {
  FluidSize out;
  if (!exchange_) {
    out.elements = state_.particles.size();
    out.fluid = state_.fluid_count;
    out.body = body_points_.size();
    out.wall = out.elements - out.fluid - out.body;
    return out;
  }
  refresh_host();
  const std::int32_t* kinds = counted_kinds();
  std::array<double, 3> count{};  // fluid, wall (dummies too), body
  for (std::size_t i = 0; i < state_.particles.size(); ++i) {
    const auto kind = static_cast<ParticleKind>(kinds[i]);
    if (kinds[i] >= 0)
      ++count[kind == ParticleKind::kFluid ? 0 : kind == ParticleKind::kBody ? 2 : 1];
  }
  ranks_.sum(count);
  out.fluid = static_cast<std::size_t>(count[0]);
  out.wall = static_cast<std::size_t>(count[1]);
  out.body = static_cast<std::size_t>(count[2]);
  out.elements = out.fluid + out.wall + out.body;
  return out;
}

template <int D>
FluidEnergy ParticleFluid<D>::energy() const {
  if (device_) return device_->energy(state_.gravity.data());
  refresh_host();
  const auto& ps = state_.particles;
  FluidEnergy e = fluid_energy(energy_share(ps, counted_kinds(), state_.gravity),
                               [&](const FluidEnergyShare<D>& share) {
                                 double sum = 0;
                                 for (std::size_t i = 0; i < ps.size(); ++i) sum += share(i);
                                 return sum;
                               });
  if (exchange_) {
    std::array<double, 3> parts{e.kinetic, e.potential, e.mass};
    ranks_.sum(parts);
    e.kinetic = parts[0];
    e.potential = parts[1];
    e.mass = parts[2];
  }
  return e;
}

template <int D>
void ParticleFluid<D>::archive_state(StateArchive& a) {
  if (gathered_ && a.reading()) {
    gather_piece(a);
    return;
  }
  if (!a.reading()) refresh_host();
  a.section("particles");
  state_.particles.archive_state(a);
  a(state_.body_point_acceleration);
  state_.cells.archive_state(a);
  if (ranks_.split()) {
    a.section("ranks");
    exchange_->archive_state(a);
  }
  a.section("model");
  archive_model(a);
  if (device_ && a.reading()) {
    device_->upload(state_.particles, state_.body_point_acceleration, state_.cells.cell_starts());
    host_current_ = true;
  }
}

template class ParticleFluid<2>;
template class ParticleFluid<3>;

}  // namespace sluice
