// The device run of wcsph_device_run.hpp over a backend that owns memory and runs loops:
//   Backend::Array<T>             memory for n values: data(), size(), resize(n),
//                                 from_host(p, n), to_host(p, n), copy_from(other)
//   Backend::Workspace            what the calls below keep between calls (owned by the caller)
//   Backend::for_each(n, body)    body(i) for i in [0, n)
//   Backend::max_of(n, value, workspace)  the largest value(i)
//   Backend::sum_of(n, value, workspace)  the sum of value(i)
//   Backend::sort_by_key(keys, values, n, bits, workspace)  stable, by the keys' lowest `bits` bits
//   Backend::inclusive_scan(in, out, n, workspace)          out[k] = in[0] + ... + in[k]
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
#include "sluice/particles/device_particle_set.hpp"

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

// Device bytes a particle takes in a run over a set of `layout`'s fields: those of the set
// (device_particle_set.hpp), and the run's own: a double of the reductions' scratch; 32-bit
// integers: the sort's keys and values and its copies of both, the scan's flags, the lists by
// kind; the packed copy, 15 floats and a count.
template <int D>
double wcsph_device_run_bytes_per_particle(const ParticleSet<D>& layout) {
  return device_bytes_per_particle(layout, shown_in_frames) + sizeof(double) + 6 * 4 + 16 * 4;
}

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

  double bytes_per_particle() const override { return bytes_per_particle_; }

  void upload(const ParticleSet<D>& host, const std::vector<Vec3>& point_acceleration) override {
    particles_.upload(host);
    n_ = particles_.size();
    bytes_per_particle_ = wcsph_device_run_bytes_per_particle(host);
    resize_scratch();
    // No stage changes a particle's kind: the count of fluid particles is the host's.
    fluid_count_ = 0;
    for (std::size_t i = 0; i < n_; ++i) fluid_count_ += host.is_fluid(i) ? 1 : 0;
    const std::uint32_t zero = 0;
    fluid_before_.from_host(&zero, 1);
    if (!point_acceleration.empty())
      point_acceleration_.from_host(point_acceleration.front().data(), 3 * setup_.body_point_count);
    // The host's set is sorted by cell: this finds the device's cell starts. The packed copy
    // is the one the host's last rates read, for the bodies' first loads.
    sort_by_cell();
    pack(true);
  }

  void download(ParticleSet<D>& host, std::vector<Vec3>& point_acceleration) const override {
    particles_.download(host);
    if (!point_acceleration.empty())
      point_acceleration_.to_host(point_acceleration.front().data(), 3 * setup_.body_point_count);
  }

  void kick_drift(Real dt) override {
    Backend::for_each(n_, WcsphKickDrift<D>{fields(), dt, setup_.constants.eos});
  }

  void sort_by_cell() override {
    const WcsphFields<D> f = fields();
    Backend::for_each(n_, device_bodies::KeepOutOfWalls<D>{walls_, f.kind, f.position, f.velocity,
                                                           f.half_velocity});
    Backend::for_each(
        n_, device_bodies::CellKey<D>{f.position, setup_.cells, key_.data(), order_.data()});
    Backend::sort_by_key(key_, order_, n_, key_bits_, workspace_);
    particles_.gather(order_.data());
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
    const WcsphFields<D> f = fields();
    Extremes e;
    e.max_speed = Backend::max_of(n_, FluidMagnitude<D>{f, f.velocity}, workspace_);
    e.max_acceleration = Backend::max_of(n_, FluidMagnitude<D>{f, f.acceleration}, workspace_);
    return e;
  }

  FluidEnergy energy(const Real* gravity) const override {
    const WcsphFields<D> f = fields();
    const auto share = FluidEnergyShare<D>::over(f.mass, f.position, f.velocity, f.kind, gravity);
    return fluid_energy(share, [&](const FluidEnergyShare<D>& part) {
      return Backend::sum_of(n_, part, workspace_);
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
    return Backend::max_of(n_, device_bodies::BadParticle<D>{checker()}, workspace_) > 0;
  }

  void remember() override { particles_.remember(shown_in_frames); }

  void download_remembered(ParticleSet<D>& host) const override {
    particles_.download_remembered(host);
  }

 private:
  // The arrays of the sort, the lists by kind, the reductions and the packed copy.
  void resize_scratch() {
    key_.resize(n_);
    order_.resize(n_);
    flag_.resize(n_);
    kind_list_.resize(n_);
    for (auto& a : packed_position_) a.resize(n_);
    for (auto& a : packed_velocity_) a.resize(n_);
    for (auto& a : packed_viscous_velocity_) a.resize(n_);
    for (auto* a : {&packed_density_, &packed_pressure_, &packed_pressure_term_, &packed_volume_,
                    &packed_fluid_, &packed_viscous_weight_})
      a->resize(n_);
    fluid_before_.resize(n_ + 1);
  }

  WcsphFields<D> fields() const { return wcsph_fields<D>(particles_, point_acceleration_.data()); }
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
    const WcsphFields<D> f = fields();
    ParticleCheck<D> c{f.position, f.velocity, f.density, f.pressure, f.kind, {}, {}};
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
    const std::int32_t* kind = fields().kind;
    Backend::for_each(n_, device_bodies::FluidFlag{kind, flag_.data()});
    Backend::inclusive_scan(flag_.data(), fluid_before_.data() + 1, n_, workspace_);
    Backend::for_each(n_, device_bodies::ListByKind{kind, fluid_before_.data(), kind_list_.data(),
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

  WcsphDeviceSetup<D, Kernel> setup_;
  DeviceParticleSet<D, Backend> particles_;
  std::size_t n_ = 0;
  double bytes_per_particle_ = 0;
  int key_bits_ = 32;
  Array<std::uint32_t> key_, order_, flag_, cell_start_, fluid_before_, kind_list_;
  std::size_t fluid_count_ = 0;
  mutable typename Backend::Workspace workspace_;
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
};

}  // namespace sluice
