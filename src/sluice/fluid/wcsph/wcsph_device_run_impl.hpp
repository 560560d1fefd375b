// The device run of wcsph_device_run.hpp over a backend that owns memory and runs loops:
//   Backend::Array<T>             memory for n values: data(), size(), resize(n),
//                                 from_host(p, n), to_host(p, n), copy_from(other)
//   Backend::for_each(n, body)    body(i) for i in [0, n)
//   Backend::max_of(n, value, scratch)  the largest value(i)
//   Backend::sum_of(n, value, scratch)  the sum of value(i)
//   Backend::sort_by_key(keys, values, n, bits)   stable, by the keys' lowest `bits` bits
//   Backend::inclusive_scan(in, out, n)           out[k] = in[0] + ... + in[k]
//   Backend::finish()             returns once every loop and copy asked for is done
//   Backend::name()
// Included by wcsph_device_host.cpp (the host's threads) and wcsph_device_cuda.cu (CUDA), so
// everything here compiles under both; the physics is the loop bodies', not this file's.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sluice/coupling/point_wrench.hpp"
#include "sluice/coupling/rigid_point.hpp"
#include "sluice/fluid/fluid_energy.hpp"
#include "sluice/fluid/particle_check.hpp"
#include "sluice/fluid/wcsph/adami_walls.hpp"
#include "sluice/fluid/wcsph/wcsph_device_run.hpp"
#include "sluice/fluid/wcsph/wcsph_loop_bodies.hpp"

namespace sluice {

namespace device_bodies {

// The cell of particle i, and i itself: the sort's key and value.
template <int D>
struct CellKey {
  const Real* position;
  CellGridView<D> cells;
  std::uint32_t* key;
  std::uint32_t* value;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    key[i] = cells.cell_of(position + D * i);
    value[i] = static_cast<std::uint32_t>(i);
  }
};

// The first particle of cell c among keys sorted by cell (n for the cells past the last).
struct CellStart {
  const std::uint32_t* key;
  std::size_t n;
  std::uint32_t* start;
  SLUICE_HOST_DEVICE void operator()(std::size_t c) const {
    std::size_t low = 0, high = n;
    while (low < high) {
      const std::size_t mid = (low + high) / 2;
      if (key[mid] < c) {
        low = mid + 1;
      } else {
        high = mid;
      }
    }
    start[c] = static_cast<std::uint32_t>(low);
  }
};

// to[k] = from[order[k]], `width` values per particle.
template <class T>
struct Gather {
  const T* from;
  T* to;
  const std::uint32_t* order;
  int width;
  SLUICE_HOST_DEVICE void operator()(std::size_t k) const {
    const std::size_t i = order[k];
    for (int a = 0; a < width; ++a) to[width * k + a] = from[width * i + a];
  }
};

// Whether particle i is fluid, as the count the scan adds up.
struct FluidFlag {
  const std::int32_t* kind;
  std::uint32_t* flag;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const { flag[i] = kind[i] == 0 ? 1u : 0u; }
};

// Particle i in the list of its kind, fluid or boundary (walls and bodies), in index order:
// fluid_before[i] is the count of fluid particles among [0, i).
struct ListByKind {
  const std::int32_t* kind;
  const std::uint32_t* fluid_before;
  std::uint32_t *fluid, *boundary;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    const std::uint32_t before = fluid_before[i];
    if (kind[i] == 0) {
      fluid[before] = static_cast<std::uint32_t>(i);
    } else {
      boundary[i - before] = static_cast<std::uint32_t>(i);
    }
  }
};

// body(list[k]): a loop over the particles of one kind alone. On a GPU a loop over every
// particle launches as many threads again that return at once, beside the working ones in
// their warps; over the list the launch is as small as the work.
template <class Body>
struct Listed {
  const std::uint32_t* list;
  Body body;
  SLUICE_HOST_DEVICE void operator()(std::size_t k) const { body(list[k]); }
};

// A body particle takes its body point's place and velocity (3D values; 2D takes x and z).
template <int D>
struct PlaceBodyPoint {
  WcsphFields<D> f;
  const Real* point_position;
  const Real* point_velocity;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    const std::int32_t k = f.body_point[i];
    if (k < 0) return;
    for (int a = 0; a < D; ++a) {
      const int a3 = D == 3 ? a : 2 * a;
      f.position[D * i + a] = point_position[3 * k + a3];
      f.velocity[D * i + a] = point_velocity[3 * k + a3];
    }
  }
};

// A fluid particle found in a wall's layers goes back on its surface.
template <int D>
struct KeepOutOfWalls {
  WallSurfacesView walls;
  const std::int32_t* kind;
  Real *position, *velocity, *half_velocity;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    if (kind[i] == 0) {
      keep_out_of_wall_solids<D>(walls, position + D * i, velocity + D * i, half_velocity + D * i);
    }
  }
};

// Body point k's place, velocity and acceleration from its body's kinematics.
struct RigidPoint {
  const Real* body_motion;
  const std::uint32_t* body;
  const Real* local;
  Real *position, *velocity, *acceleration;
  SLUICE_HOST_DEVICE void operator()(std::size_t k) const {
    const Real* m = body_motion + kBodyMotionReals * body[k];
    rigid_point_position(m, local + 3 * k, position + 3 * k);
    rigid_point_velocity(m, local + 3 * k, velocity + 3 * k);
    rigid_point_acceleration(m, local + 3 * k, acceleration + 3 * k);
  }
};

// Body b's force and moment from its points' forces (point_wrench.hpp), 6 reals per body.
struct BodyWrench {
  const Real* point_position;
  const Real* point_force;
  const std::uint32_t* first;
  const Real* centre;
  Real* wrench;
  SLUICE_HOST_DEVICE void operator()(std::size_t b) const {
    sum_point_wrenches(point_position, point_force, first[b], first[b + 1], centre + 3 * b,
                       wrench + 6 * b);
  }
};

// 1 for a particle gone wrong, else 0: their largest tells whether there is one.
template <int D>
struct BadParticle {
  ParticleCheck<D> check;
  SLUICE_HOST_DEVICE double operator()(std::size_t i) const {
    return check(i) != ParticleProblem::kNone ? 1.0 : 0.0;
  }
};

}  // namespace device_bodies

template <int D, class Kernel, class Backend>
class WcsphDeviceRunOn final : public WcsphDeviceRun<D> {
  template <class T>
  using Array = typename Backend::template Array<T>;
  using typename WcsphDeviceRun<D>::Extremes;

 public:
  explicit WcsphDeviceRunOn(const WcsphDeviceSetup<D, Kernel>& setup) : setup_(setup) {
    cell_start_.resize(setup.cell_count + 1);
    point_position_.resize(3 * setup.body_point_count);
    point_velocity_.resize(3 * setup.body_point_count);
    point_acceleration_.resize(3 * setup.body_point_count);
    point_force_.resize(3 * setup.body_point_count);
    const std::size_t bodies = setup.body_first.empty() ? 0 : setup.body_first.size() - 1;
    body_first_.resize(bodies + 1);
    if (bodies > 0) body_first_.from_host(setup.body_first.data(), bodies + 1);
    body_centre_.resize(3 * bodies);
    body_motion_.resize(kBodyMotionReals * bodies);
    walls_ = setup.walls;
    wall_plane_.resize(6 * walls_.planes);
    wall_box_.resize(6 * walls_.boxes);
    if (walls_.planes > 0) wall_plane_.from_host(setup.walls.plane, 6 * walls_.planes);
    if (walls_.boxes > 0) wall_box_.from_host(setup.walls.box, 6 * walls_.boxes);
    walls_.plane = wall_plane_.data();
    walls_.box = wall_box_.data();
    point_local_.resize(3 * setup.body_point_count);
    point_body_.resize(setup.body_point_count);
    if (setup.body_point_count > 0) {
      point_local_.from_host(setup.point_local.data(), 3 * setup.body_point_count);
      std::vector<std::uint32_t> body(setup.body_point_count);
      for (std::size_t b = 0; b < bodies; ++b) {
        for (std::uint32_t k = setup.body_first[b]; k < setup.body_first[b + 1]; ++k) {
          body[k] = static_cast<std::uint32_t>(b);
        }
      }
      point_body_.from_host(body.data(), setup.body_point_count);
    }
    wrench_.resize(6 * bodies);
    std::uint32_t bits = 1;
    while ((std::size_t{1} << bits) <= setup.cell_count && bits < 32) ++bits;
    key_bits_ = static_cast<int>(bits);
  }

  std::string name() const override { return Backend::name(); }

  double bytes_per_particle() const override { return wcsph_device_bytes_per_particle(D); }

  void upload(const WcsphFields<D>& host) override {
    n_ = host.size;
    resize_all();
    // No stage changes a particle's kind: the count of fluid particles is the host's.
    fluid_count_ = 0;
    for (std::size_t i = 0; i < n_; ++i) fluid_count_ += host.kind[i] == 0 ? 1 : 0;
    const std::uint32_t zero = 0;
    fluid_before_.from_host(&zero, 1);
    position_.from_host(host.position, D * n_);
    velocity_.from_host(host.velocity, D * n_);
    density_.from_host(host.density, n_);
    pressure_.from_host(host.pressure, n_);
    mass_.from_host(host.mass, n_);
    kind_.from_host(host.kind, n_);
    body_point_.from_host(host.body_point, n_);
    acceleration_.from_host(host.acceleration, D * n_);
    density_rate_.from_host(host.density_rate, n_);
    half_velocity_.from_host(host.half_velocity, D * n_);
    half_density_.from_host(host.half_density, n_);
    wall_velocity_.from_host(host.wall_velocity, D * n_);
    point_acceleration_.from_host(host.body_point_acceleration, 3 * setup_.body_point_count);
    // The host's set is sorted by cell: this finds the device's cell starts. The packed copy
    // is the one the host's last rates read, for the bodies' first loads.
    sort_by_cell();
    pack(true);
  }

  void download(const WcsphFields<D>& host) const override {
    position_.to_host(host.position, D * n_);
    velocity_.to_host(host.velocity, D * n_);
    density_.to_host(host.density, n_);
    pressure_.to_host(host.pressure, n_);
    mass_.to_host(const_cast<Real*>(host.mass), n_);
    kind_.to_host(const_cast<std::int32_t*>(host.kind), n_);
    body_point_.to_host(const_cast<std::int32_t*>(host.body_point), n_);
    acceleration_.to_host(host.acceleration, D * n_);
    density_rate_.to_host(host.density_rate, n_);
    half_velocity_.to_host(host.half_velocity, D * n_);
    half_density_.to_host(host.half_density, n_);
    wall_velocity_.to_host(host.wall_velocity, D * n_);
    point_acceleration_.to_host(const_cast<Real*>(host.body_point_acceleration),
                                3 * setup_.body_point_count);
  }

  void kick_drift(Real dt) override {
    Backend::for_each(n_, WcsphKickDrift<D>{fields(), dt, setup_.constants.eos});
  }

  void sort_by_cell() override {
    Backend::for_each(n_,
                      device_bodies::KeepOutOfWalls<D>{walls_, kind_.data(), position_.data(),
                                                       velocity_.data(), half_velocity_.data()});
    Backend::for_each(
        n_, device_bodies::CellKey<D>{position_.data(), setup_.cells, key_.data(), order_.data()});
    Backend::sort_by_key(key_, order_, n_, key_bits_);
    gather(position_, D);
    gather(velocity_, D);
    gather(density_, 1);
    gather(pressure_, 1);
    gather(mass_, 1);
    gather(kind_, 1);
    gather(body_point_, 1);
    gather(acceleration_, D);
    gather(density_rate_, 1);
    gather(half_velocity_, D);
    gather(half_density_, 1);
    gather(wall_velocity_, D);
    Backend::for_each(setup_.cell_count + 1,
                      device_bodies::CellStart{key_.data(), n_, cell_start_.data()});
    list_by_kind();
  }

  void set_body_motion(const std::vector<Real>& body_motion) override {
    if (setup_.body_point_count == 0) return;
    body_motion_.from_host(body_motion.data(), body_motion.size());
    Backend::for_each(
        setup_.body_point_count,
        device_bodies::RigidPoint{body_motion_.data(), point_body_.data(), point_local_.data(),
                                  point_position_.data(), point_velocity_.data(),
                                  point_acceleration_.data()});
    Backend::for_each(n_, device_bodies::PlaceBodyPoint<D>{fields(), point_position_.data(),
                                                           point_velocity_.data()});
  }

  void update_walls() override {
    pack(false);
    for_each_boundary(AdamiWall<D, Kernel>{neighbourhood()});
  }

  void compute_rates() override {
    pack(true);
    for_each_fluid(WcsphRates<D, Kernel>{neighbourhood()});
  }

  void kick(Real dt) override {
    Backend::for_each(n_, WcsphKick<D>{fields(), dt, setup_.constants.eos});
  }

  Extremes extremes() const override {
    Extremes e;
    e.max_speed = Backend::max_of(n_, FluidMagnitude<D>{fields(), velocity_.data()}, scratch_);
    e.max_acceleration =
        Backend::max_of(n_, FluidMagnitude<D>{fields(), acceleration_.data()}, scratch_);
    return e;
  }

  FluidEnergy energy(const Real* gravity) const override {
    const auto share = FluidEnergyShare<D>::over(mass_.data(), position_.data(), velocity_.data(),
                                                 kind_.data(), gravity);
    return fluid_energy(share, [&](const FluidEnergyShare<D>& part) {
      return Backend::sum_of(n_, part, scratch_);
    });
  }

  void body_loads(const std::vector<Vec3>& centre, std::vector<Wrench>& out) const override {
    const std::size_t bodies = centre.size();
    out.assign(bodies, Wrench{});
    if (setup_.body_point_count == 0 || bodies == 0) return;
    for_each_boundary(WcsphBodyPointForce<D, Kernel>{neighbourhood(), point_force_.data()});
    body_centre_.from_host(centre.front().data(), 3 * bodies);
    Backend::for_each(
        bodies, device_bodies::BodyWrench{point_position_.data(), point_force_.data(),
                                          body_first_.data(), body_centre_.data(), wrench_.data()});
    std::vector<Real> wrench(6 * bodies);
    wrench_.to_host(wrench.data(), 6 * bodies);
    for (std::size_t b = 0; b < bodies; ++b) {
      out[b].force = Vec3(wrench[6 * b], wrench[6 * b + 1], wrench[6 * b + 2]);
      out[b].moment = Vec3(wrench[6 * b + 3], wrench[6 * b + 4], wrench[6 * b + 5]);
    }
  }

  void finish() const override { Backend::finish(); }

  bool any_problem() const override {
    return Backend::max_of(n_, device_bodies::BadParticle<D>{checker()}, scratch_) > 0;
  }

  void remember() override {
    good_position_.copy_from(position_);
    good_velocity_.copy_from(velocity_);
    good_density_.copy_from(density_);
    good_pressure_.copy_from(pressure_);
    good_kind_.copy_from(kind_);
    good_body_point_.copy_from(body_point_);
  }

  void download_remembered(const WcsphFields<D>& host) const override {
    good_position_.to_host(host.position, D * n_);
    good_velocity_.to_host(host.velocity, D * n_);
    good_density_.to_host(host.density, n_);
    good_pressure_.to_host(host.pressure, n_);
    good_kind_.to_host(const_cast<std::int32_t*>(host.kind), n_);
    good_body_point_.to_host(const_cast<std::int32_t*>(host.body_point), n_);
  }

 private:
  void resize_all() {
    for (auto* a : {&position_, &velocity_, &acceleration_, &half_velocity_, &wall_velocity_})
      a->resize(D * n_);
    for (auto* a : {&density_, &pressure_, &mass_, &density_rate_, &half_density_}) a->resize(n_);
    kind_.resize(n_);
    body_point_.resize(n_);
    key_.resize(n_);
    order_.resize(n_);
    flag_.resize(n_);
    kind_list_.resize(n_);
    gather_vector_.resize(D * n_);
    gather_scalar_.resize(n_);
    gather_int_.resize(n_);
    scratch_.resize(n_);
    for (auto& a : packed_position_) a.resize(n_);
    for (auto& a : packed_velocity_) a.resize(n_);
    for (auto& a : packed_viscous_velocity_) a.resize(n_);
    for (auto* a : {&packed_density_, &packed_pressure_, &packed_pressure_term_, &packed_volume_,
                    &packed_fluid_, &packed_viscous_weight_})
      a->resize(n_);
    fluid_before_.resize(n_ + 1);
  }

  WcsphFields<D> fields() const {
    WcsphFields<D> f;
    f.size = n_;
    f.position = mutable_data(position_);
    f.velocity = mutable_data(velocity_);
    f.density = mutable_data(density_);
    f.pressure = mutable_data(pressure_);
    f.mass = mass_.data();
    f.kind = kind_.data();
    f.body_point = body_point_.data();
    f.acceleration = mutable_data(acceleration_);
    f.density_rate = mutable_data(density_rate_);
    f.half_velocity = mutable_data(half_velocity_);
    f.half_density = mutable_data(half_density_);
    f.wall_velocity = mutable_data(wall_velocity_);
    f.body_point_acceleration = point_acceleration_.data();
    return f;
  }
  template <class T>
  static T* mutable_data(const Array<T>& a) {
    return const_cast<T*>(a.data());
  }

  WcsphNeighbourhood<D, Kernel> neighbourhood() const {
    return {fields(), packed_view(), cells(), setup_.constants};
  }

  CellGridView<D> cells() const {
    CellGridView<D> c = setup_.cells;
    c.cell_start = cell_start_.data();
    return c;
  }

  ParticleCheck<D> checker() const {
    ParticleCheck<D> c{position_.data(),
                       velocity_.data(),
                       density_.data(),
                       pressure_.data(),
                       kind_.data(),
                       {},
                       {}};
    for (int a = 0; a < D; ++a) {
      c.escape_min[a] = setup_.escape_min[a];
      c.escape_max[a] = setup_.escape_max[a];
    }
    return c;
  }

  PackedParticles::Arrays packed_arrays() const {
    PackedParticles::Arrays p{};
    for (int a = 0; a < 3; ++a) {
      p.position[a] = mutable_data(packed_position_[a]);
      p.velocity[a] = mutable_data(packed_velocity_[a]);
      p.viscous_velocity[a] = mutable_data(packed_viscous_velocity_[a]);
    }
    p.density = mutable_data(packed_density_);
    p.pressure = mutable_data(packed_pressure_);
    p.pressure_term = mutable_data(packed_pressure_term_);
    p.volume = mutable_data(packed_volume_);
    p.fluid = mutable_data(packed_fluid_);
    p.viscous_weight = mutable_data(packed_viscous_weight_);
    p.fluid_before = mutable_data(fluid_before_);
    return p;
  }
  PackedParticles::View packed_view() const { return packed_arrays().view(); }

  void pack(bool with_rates) {
    Backend::for_each(
        n_, WcsphPack<D>{fields(), packed_arrays(), setup_.constants.no_slip, with_rates});
  }

  // After each sort: fluid_before (fluid_before[k] = fluid particles among [0, k); its first
  // entry, 0, is written once) and the lists by kind, the fluid first, in kind_list_.
  void list_by_kind() {
    Backend::for_each(n_, device_bodies::FluidFlag{kind_.data(), flag_.data()});
    Backend::inclusive_scan(flag_.data(), fluid_before_.data() + 1, n_);
    Backend::for_each(
        n_, device_bodies::ListByKind{kind_.data(), fluid_before_.data(), kind_list_.data(),
                                      kind_list_.data() + fluid_count_});
  }
  template <class Body>
  void for_each_fluid(const Body& body) const {
    Backend::for_each(fluid_count_, device_bodies::Listed<Body>{kind_list_.data(), body});
  }
  template <class Body>
  void for_each_boundary(const Body& body) const {
    Backend::for_each(n_ - fluid_count_,
                      device_bodies::Listed<Body>{kind_list_.data() + fluid_count_, body});
  }

  // Reorders a field by the sort's order through a scratch array of the same size, which the
  // field then swaps with (so each scratch keeps its size).
  template <class T>
  void gather(Array<T>& field, int width) {
    Array<T>& scratch = scratch_for<T>(width);
    Backend::for_each(n_,
                      device_bodies::Gather<T>{field.data(), scratch.data(), order_.data(), width});
    field.swap(scratch);
  }
  template <class T>
  Array<T>& scratch_for(int width) {
    if constexpr (std::is_same_v<T, Real>) {
      return width == 1 ? gather_scalar_ : gather_vector_;
    } else {
      return gather_int_;
    }
  }

  WcsphDeviceSetup<D, Kernel> setup_;
  std::size_t n_ = 0;
  int key_bits_ = 32;
  Array<Real> position_, velocity_, density_, pressure_, mass_, acceleration_, density_rate_,
      half_velocity_, half_density_, wall_velocity_;
  Array<std::int32_t> kind_, body_point_;
  Array<std::uint32_t> key_, order_, flag_, cell_start_, fluid_before_, kind_list_;
  std::size_t fluid_count_ = 0;
  Array<Real> gather_vector_, gather_scalar_;
  Array<std::int32_t> gather_int_;
  mutable Array<double> scratch_;
  Array<float> packed_position_[3], packed_velocity_[3], packed_viscous_velocity_[3];
  Array<float> packed_density_, packed_pressure_, packed_pressure_term_, packed_volume_,
      packed_fluid_, packed_viscous_weight_;
  Array<Real> point_position_, point_velocity_, point_acceleration_;
  mutable Array<Real> point_force_;
  Array<std::uint32_t> body_first_, point_body_;
  Array<Real> body_motion_, point_local_;
  WallSurfacesView walls_;  // over wall_plane_ and wall_box_
  Array<Real> wall_plane_, wall_box_;
  mutable Array<Real> body_centre_, wrench_;
  Array<Real> good_position_, good_velocity_, good_density_, good_pressure_;
  Array<std::int32_t> good_kind_, good_body_point_;
};

}  // namespace sluice
