// The particle base's services on a device (particle_fluid.hpp's, where the particles live in a
// device's memory for the whole run): the neighbour sort with the walls' put-back, the lists by
// kind, the body points and the bodies' loads, the divergence guard's check and last good
// state, and the fluid's energy, over a DeviceParticleSet. A model's device run holds one and
// adds its own stages (wcsph_device_run_impl.hpp). Over a backend that owns memory and runs loops:
//   Backend::Array<T>             memory for n values: data(), size(), resize(n), swap(other),
//                                 from_host(p, n), to_host(p, n), copy_from(other)
//   Backend::Workspace            what the calls below keep between calls (owned by the caller)
//   Backend::for_each(n, body)    body(i) for i in [0, n)
//   Backend::max_of(n, value, workspace)  the largest value(i)
//   Backend::sum_of(n, value, workspace)  the sum of value(i)
//   Backend::sort_by_key(keys, values, n, bits, workspace)  stable, by the keys' lowest `bits` bits
//   Backend::inclusive_scan(in, out, n, workspace)          out[k] = in[0] + ... + in[k]
//   Backend::finish()             returns once every loop and copy asked for is done
//   Backend::name()
// exec/host_backend.hpp (the emulated device) and exec/cuda_backend.cuh are the two; so
// everything here compiles under both nvcc and the host's compiler.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sluice/coupling/body_motion.hpp"
#include "sluice/coupling/point_wrench.hpp"
#include "sluice/coupling/rigid_point.hpp"
#include "sluice/fluid/fluid_energy.hpp"
#include "sluice/fluid/particle_check.hpp"
#include "sluice/fluid/particle_device.hpp"
#include "sluice/fluid/wall_surfaces.hpp"
#include "sluice/neighbor/cell_list.hpp"
#include "sluice/particles/device_particle_set.hpp"

namespace sluice {

// What the base's services on a device need besides the particles: the cell grid (its
// geometry; the device keeps its own cell starts), the body points, the walls a fluid particle
// is put back from (on the host; the run copies their arrays) and the domain a fluid particle
// must not leave.
template <int D>
struct ParticleDeviceSetup {
  CellGridView<D> cells;
  std::size_t cell_count = 0;
  std::size_t body_point_count = 0;
  std::vector<std::uint32_t> body_first = {};  // BodyPoints::first_of_each_body (bodies + 1)
  std::vector<Real> point_local = {};          // each body point's place in its body (3 reals)
  WallSurfacesView walls = {};
  Real escape_min[D] = {}, escape_max[D] = {};
  // The field that a particle put back on a wall loses its speed into the wall from too, beside
  // its velocity (ParticleFluid::carry_through_put_back); empty for none.
  std::string carried_velocity = {};
};

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
  const std::int32_t* body_point;
  Real *position, *velocity;
  const Real* point_position;
  const Real* point_velocity;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    const std::int32_t k = body_point[i];
    if (k < 0) return;
    for (int a = 0; a < D; ++a) {
      const int a3 = D == 3 ? a : 2 * a;
      position[D * i + a] = point_position[3 * k + a3];
      velocity[D * i + a] = point_velocity[3 * k + a3];
    }
  }
};

// A fluid particle found in a wall's layers goes back on its surface.
template <int D>
struct KeepOutOfWalls {
  WallSurfacesView walls;
  const std::int32_t* kind;
  Real *position, *velocity, *carried;  // carried: nullptr for none
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    if (kind[i] == 0) {
      keep_out_of_wall_solids<D>(walls, position + D * i, velocity + D * i,
                                 carried ? carried + D * i : nullptr);
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

template <int D, class Backend>
class ParticleDeviceRun {
  template <class T>
  using Array = typename Backend::template Array<T>;

 public:
  explicit ParticleDeviceRun(const ParticleDeviceSetup<D>& setup) : setup_(setup) {
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

  // Device bytes a particle takes with the fields of `layout`: the set's
  // (device_particle_set.hpp) and the base's own: a double of the reductions' scratch; 32-bit
  // integers: the sort's keys and values and its copies of both, the scan's flags, the lists by
  // kind, the count of fluid before each particle.
  static double bytes_per_particle(const ParticleSet<D>& layout) {
    return device_bytes_per_particle(layout, shown_in_frames) + sizeof(double) + 7 * 4;
  }

  DeviceParticleSet<D, Backend>& particles() { return particles_; }
  const DeviceParticleSet<D, Backend>& particles() const { return particles_; }
  std::size_t size() const { return particles_.size(); }
  std::size_t fluid_count() const { return fluid_count_; }
  typename Backend::Workspace& workspace() const { return workspace_; }

  // Every field of `host`, the body points' accelerations and the cells of the host's last sort
  // to the device, and the lists by kind.
  void upload(const ParticleSet<D>& host, const std::vector<Vec3>& point_acceleration,
              const std::vector<std::uint32_t>& cell_start) {
    particles_.upload(host);
    find_fields();
    const std::size_t n = size();
    key_.resize(n);
    order_.resize(n);
    flag_.resize(n);
    kind_list_.resize(n);
    fluid_before_.resize(n + 1);
    // No stage changes a particle's kind: the count of fluid particles is the host's.
    fluid_count_ = 0;
    for (std::size_t i = 0; i < n; ++i) fluid_count_ += host.is_fluid(i) ? 1 : 0;
    const std::uint32_t zero = 0;
    fluid_before_.from_host(&zero, 1);
    if (!point_acceleration.empty())
      point_acceleration_.from_host(point_acceleration.front().data(), 3 * setup_.body_point_count);
    cell_start_.from_host(cell_start.data(), cell_start.size());
    list_by_kind();
  }
  // The device's fields into `host` (a set of the same fields), in the device's order, and the
  // body points' accelerations.
  void download(ParticleSet<D>& host, std::vector<Vec3>& point_acceleration) const {
    particles_.download(host);
    if (!point_acceleration.empty())
      point_acceleration_.to_host(point_acceleration.front().data(), 3 * setup_.body_point_count);
  }

  void download_cell_starts(std::vector<std::uint32_t>& start) const {
    start.resize(cell_start_.size());
    cell_start_.to_host(start.data(), start.size());
  }

  // The neighbour stage: puts back fluid found in a wall's layers, sorts by cell, and lists the
  // particles by kind.
  void sort_by_cell() {
    const std::size_t n = size();
    Backend::for_each(
        n, device_bodies::KeepOutOfWalls<D>{walls_, f_.kind, f_.position, f_.velocity, f_.carried});
    Backend::for_each(
        n, device_bodies::CellKey<D>{f_.position, setup_.cells, key_.data(), order_.data()});
    Backend::sort_by_key(key_, order_, n, key_bits_, workspace_);
    particles_.gather(order_.data());
    find_fields();  // the gather swapped every field's array
    Backend::for_each(setup_.cell_count + 1,
                      device_bodies::CellStart{key_.data(), n, cell_start_.data()});
    list_by_kind();
  }

  // The bodies moved: `body_motion` holds each body's kinematics (pack_body_motion); the
  // device places their points (rigid_point.hpp, the host's arithmetic) and their particles.
  void set_body_motion(const std::vector<Real>& body_motion) {
    if (setup_.body_point_count == 0) return;
    body_motion_.from_host(body_motion.data(), body_motion.size());
    Backend::for_each(
        setup_.body_point_count,
        device_bodies::RigidPoint{body_motion_.data(), point_body_.data(), point_local_.data(),
                                  point_position_.data(), point_velocity_.data(),
                                  point_acceleration_.data()});
    Backend::for_each(
        size(), device_bodies::PlaceBodyPoint<D>{f_.body_point, f_.position, f_.velocity,
                                                 point_position_.data(), point_velocity_.data()});
  }
  const Real* point_acceleration() const { return point_acceleration_.data(); }

  // The fluid's force on each body and its moment about the body's `centre` (one per body):
  // point_force(forces) is the model's loop body over the boundary particles that writes each
  // body point's force into `forces` (3 reals a point); summed over the body's points on the
  // device (point_wrench.hpp, the host's arithmetic), so that 6 reals per body come back.
  template <class PointForce>
  void body_loads(const std::vector<Vec3>& centre, std::vector<Wrench>& out,
                  PointForce&& point_force) const {
    const std::size_t bodies = centre.size();
    out.assign(bodies, Wrench{});
    if (setup_.body_point_count == 0 || bodies == 0) return;
    for_each_boundary(point_force(const_cast<Real*>(point_force_.data())));
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

  // The grid with the device's cell starts, and the count of fluid particles among [0, k) for
  // each k (its first entry 0), as of the last sort.
  CellGridView<D> cells() const {
    CellGridView<D> c = setup_.cells;
    c.cell_start = cell_start_.data();
    return c;
  }
  std::uint32_t* fluid_before() const { return const_cast<std::uint32_t*>(fluid_before_.data()); }

  // body(i) for every particle, for the fluid ones, for the boundary (walls and bodies) ones.
  template <class Body>
  void for_each(const Body& body) const {
    Backend::for_each(size(), body);
  }
  template <class Body>
  void for_each_fluid(const Body& body) const {
    Backend::for_each(fluid_count_, device_bodies::Listed<Body>{kind_list_.data(), body});
  }
  template <class Body>
  void for_each_boundary(const Body& body) const {
    Backend::for_each(size() - fluid_count_,
                      device_bodies::Listed<Body>{kind_list_.data() + fluid_count_, body});
  }
  template <class Value>
  double max_of(const Value& value) const {
    return Backend::max_of(size(), value, workspace_);
  }

  // The fluid's kinetic and potential energy and mass (fluid_energy.hpp), summed on the device.
  // `gravity` holds D reals.
  FluidEnergy energy(const Real* gravity) const {
    const auto share =
        FluidEnergyShare<D>::over(f_.mass, f_.position, f_.velocity, f_.kind, gravity);
    return fluid_energy(share, [&](const FluidEnergyShare<D>& part) {
      return Backend::sum_of(size(), part, workspace_);
    });
  }

  // Whether a particle went wrong (particle_check.hpp); the host's copy then names it.
  bool any_problem() const { return max_of(device_bodies::BadParticle<D>{checker()}) > 0; }

  // Keeps the fields a frame shows as the last good state (on the device), and copies them back
  // into a set of the host's fields.
  void remember() { particles_.remember(shown_in_frames); }
  void download_remembered(ParticleSet<D>& host) const { particles_.download_remembered(host); }

  void finish() const { Backend::finish(); }

 private:
  // The engine's fields' arrays, found by name once after each upload and sort (the only times
  // they move), not in every stage.
  struct EngineFields {
    Real *position = nullptr, *velocity = nullptr, *density = nullptr, *pressure = nullptr;
    Real *mass = nullptr, *carried = nullptr;  // carried: nullptr for none
    std::int32_t *kind = nullptr, *body_point = nullptr;
  };
  void find_fields() {
    auto reals = [&](const char* name) { return particles_.template components<Real>(name); };
    f_.position = reals("position");
    f_.velocity = reals("velocity");
    f_.density = reals("density");
    f_.pressure = reals("pressure");
    f_.mass = reals("mass");
    f_.carried = setup_.carried_velocity.empty() ? nullptr : reals(setup_.carried_velocity.c_str());
    f_.kind = particles_.template components<std::int32_t>("kind");
    f_.body_point = particles_.template components<std::int32_t>("body_point");
  }

  ParticleCheck<D> checker() const {
    ParticleCheck<D> c{f_.position, f_.velocity, f_.density, f_.pressure, f_.kind, {}, {}};
    for (int a = 0; a < D; ++a) {
      c.escape_min[a] = setup_.escape_min[a];
      c.escape_max[a] = setup_.escape_max[a];
    }
    return c;
  }

  // After each sort: fluid_before (its first entry, 0, is written once) and the lists by kind,
  // the fluid first, in kind_list_.
  void list_by_kind() {
    const std::size_t n = size();
    Backend::for_each(n, device_bodies::FluidFlag{f_.kind, flag_.data()});
    Backend::inclusive_scan(flag_.data(), fluid_before_.data() + 1, n, workspace_);
    Backend::for_each(n, device_bodies::ListByKind{f_.kind, fluid_before_.data(), kind_list_.data(),
                                                   kind_list_.data() + fluid_count_});
  }

  ParticleDeviceSetup<D> setup_;
  DeviceParticleSet<D, Backend> particles_;
  EngineFields f_;
  std::size_t fluid_count_ = 0;
  int key_bits_ = 32;
  Array<std::uint32_t> key_, order_, flag_, cell_start_, fluid_before_, kind_list_;
  mutable typename Backend::Workspace workspace_;
  Array<Real> point_position_, point_velocity_, point_acceleration_;
  mutable Array<Real> point_force_;
  Array<std::uint32_t> body_first_, point_body_;
  Array<Real> body_motion_, point_local_;
  WallSurfacesView walls_;  // over wall_plane_ and wall_box_
  Array<Real> wall_plane_, wall_box_;
  mutable Array<Real> body_centre_, wrench_;
};

// The particle base's services of a device (particle_device.hpp: transfers, the neighbour stage,
// the body points, the energy, the check, the last good state) over a backend, as a model's
// device run inherits them: `Interface` is ParticleDevice<D> or a model's extension of it, whose
// own stages the model's run adds over base_. Uploads and the bytes per particle are each run's.
template <int D, class Backend, class Interface>
class ParticleDeviceServices : public Interface {
 public:
  explicit ParticleDeviceServices(const ParticleDeviceSetup<D>& setup) : base_(setup) {}

  std::string name() const override { return Backend::name(); }
  void download(ParticleSet<D>& host, std::vector<Vec3>& point_acceleration) const override {
    base_.download(host, point_acceleration);
  }
  void download_cell_starts(std::vector<std::uint32_t>& start) const override {
    base_.download_cell_starts(start);
  }
  void sort_by_cell() override { base_.sort_by_cell(); }
  void set_body_motion(const std::vector<Real>& body_motion) override {
    base_.set_body_motion(body_motion);
  }
  FluidEnergy energy(const Real* gravity) const override { return base_.energy(gravity); }
  bool any_problem() const override { return base_.any_problem(); }
  void remember() override { base_.remember(); }
  void download_remembered(ParticleSet<D>& host) const override { base_.download_remembered(host); }
  void finish() const override { base_.finish(); }

 protected:
  ParticleDeviceRun<D, Backend> base_;
};

// The base's services alone, as the device ParticleFluid runs on for a model without a device
// run of its own; run() gives the model's loops (ParticleFluid::for_each_particle) the
// particles there.
template <int D, class Backend>
class ParticleDeviceOn final : public ParticleDeviceServices<D, Backend, ParticleDevice<D>> {
  using Services = ParticleDeviceServices<D, Backend, ParticleDevice<D>>;

 public:
  using Services::Services;
  ParticleDeviceRun<D, Backend>& run() { return this->base_; }

  double bytes_per_particle() const override { return bytes_per_particle_; }
  void upload(const ParticleSet<D>& host, const std::vector<Vec3>& point_acceleration,
              const std::vector<std::uint32_t>& cell_start) override {
    this->base_.upload(host, point_acceleration, cell_start);
    bytes_per_particle_ = ParticleDeviceRun<D, Backend>::bytes_per_particle(host);
  }

 private:
  double bytes_per_particle_ = 0;
};

}  // namespace sluice
