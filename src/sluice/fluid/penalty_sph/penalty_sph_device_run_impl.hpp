// The device run of penalty_sph_device_run.hpp: the particle base's services on the device
// (particle_device_run.hpp, which describes what a backend offers) and penalty-sph's stages,
// the loop bodies the host runs over the device's arrays. Included by
// penalty_sph_device_run.cpp (the host's threads, the emulated device).
//
// The solids are gathered as SolidParticles gathers them on the host: each kind listed in
// particle order (a flag, its scan, a compaction), then sorted stably by cell on a grid of
// their own; the drift's lists likewise. So every array holds what the host's holds, in its
// order, and the drift's sums come out the same.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "sluice/fluid/fluid_vector_norm.hpp"
#include "sluice/fluid/particle_device_run.hpp"
#include "sluice/fluid/penalty_sph/penalty_drift.hpp"
#include "sluice/fluid/penalty_sph/penalty_sph_device_run.hpp"
#include "sluice/fluid/penalty_sph/penalty_sph_loop_bodies.hpp"

namespace sluice {

namespace penalty_device {

// 1 where particle i belongs in a list, for the scan that numbers the list.
struct FixedSolidFlag {  // a wall's or a fixed layer's particle
  const std::int32_t* kind;
  const std::int32_t* body_point;
  std::uint32_t* flag;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    flag[i] = kind[i] != 0 && body_point[i] < 0 ? 1u : 0u;
  }
};
struct BodyParticleFlag {
  const std::int32_t* body_point;
  std::uint32_t* flag;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    flag[i] = body_point[i] >= 0 ? 1u : 0u;
  }
};
// A fluid particle out of the bodies' reach over the step (`far`), or in it.
template <int D>
struct ReachFlag {
  const std::int32_t* kind;
  PenaltyOutOfBodiesReach<D> out_of_reach;
  bool far;
  std::uint32_t* flag;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    flag[i] = kind[i] == 0 && out_of_reach(i) == far ? 1u : 0u;
  }
};
// list[k] = the k-th flagged particle, from the flags' inclusive scan.
struct Compact {
  const std::uint32_t* flag;
  const std::uint32_t* counted;
  std::uint32_t* list;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    if (flag[i]) list[counted[i] - 1] = static_cast<std::uint32_t>(i);
  }
};

// Coordinate `axis` of x[n] (sign -1: its negative, so that a largest value is a least).
template <int D>
struct Coordinate {
  const Vec<D>* x;
  int axis;
  Real sign;
  SLUICE_HOST_DEVICE double operator()(std::size_t n) const { return sign * x[n][axis]; }
};
// |v| of listed particle list[n].
template <int D>
struct ListedSpeed {
  const std::uint32_t* list;
  const Vec<D>* velocity;
  SLUICE_HOST_DEVICE double operator()(std::size_t n) const { return velocity[list[n]].norm(); }
};
// (L_b + l0) / 2 of a solid particle: the reach, which bounds the contact support from below.
template <int D>
struct SolidReach {
  const std::int32_t* kind;
  const Real* spacing;
  Real fluid_spacing;
  SLUICE_HOST_DEVICE double operator()(std::size_t i) const {
    return kind[i] != 0 ? (spacing[i] + fluid_spacing) / 2
                        : -std::numeric_limits<double>::infinity();
  }
};

// Where listed solid n starts the drift: where it stands (fixed), or where the last exchange
// left its body point (start, one per point).
template <int D>
struct SolidStart {
  const std::uint32_t* list;
  const Vec<D>* position;
  const std::int32_t* body_point;
  const Vec<D>* start;  // null for fixed solids
  Vec<D>* x;
  SLUICE_HOST_DEVICE void operator()(std::size_t n) const {
    const std::uint32_t i = list[n];
    x[n] = start ? start[body_point[i]] : position[i];
  }
};
template <int D>
struct SolidCell {
  CellGridView<D> grid;
  const Vec<D>* x;
  std::uint32_t* key;
  std::uint32_t* value;
  SLUICE_HOST_DEVICE void operator()(std::size_t n) const {
    key[n] = grid.cell_of(x[n].data());
    value[n] = static_cast<std::uint32_t>(n);
  }
};
// Solid `offset + k`, the k-th of the list in cell order (SolidParticles::sorted_grid): with
// `start`, moving from there to where it stands over dt, and start then set to that place.
template <int D>
struct PlaceSolid {
  const std::uint32_t* order;
  const std::uint32_t* list;
  const Vec<D>* x;
  const Vec<D>* position;
  const std::int32_t* body_point;
  const Real* spacing;
  Real fluid_spacing, dt;
  Vec<D>* start;  // null for fixed solids
  std::size_t offset;
  Vec<D>* solid_position;
  Vec<D>* solid_velocity;
  Real* reach;
  Real* volume;
  std::int32_t* solid_body_point;
  SLUICE_HOST_DEVICE void operator()(std::size_t k) const {
    const std::uint32_t n = order[k];
    const std::uint32_t i = list[n];
    const std::int32_t point = body_point[i];
    const std::size_t s = offset + k;
    solid_position[s] = x[n];
    solid_velocity[s] = start && dt > 0 ? Vec<D>((position[i] - x[n]) / dt) : Vec<D>::Zero();
    reach[s] = (spacing[i] + fluid_spacing) / 2;
    volume[s] = std::pow(spacing[i], D);
    solid_body_point[s] = point;
    if (start) start[point] = position[i];
  }
};
// Each body point's start of the drift: where its particle stands.
template <int D>
struct BodyStart {
  const std::uint32_t* list;
  const Vec<D>* position;
  const std::int32_t* body_point;
  Vec<D>* start;
  SLUICE_HOST_DEVICE void operator()(std::size_t n) const {
    const std::uint32_t i = list[n];
    start[body_point[i]] = position[i];
  }
};

// The tallies' entries in particle order, keyed by body point, for the sort that groups them
// (`end`: the counts' inclusive scan).
template <int D, int kTally>
struct TallyKeys {
  const BodyImpulse<D>* records;
  const std::uint32_t* count;
  const std::uint32_t* end;
  std::uint32_t* key;
  std::uint32_t* value;
  SLUICE_HOST_DEVICE void operator()(std::size_t n) const {
    const std::uint32_t first = end[n] - count[n];
    for (std::uint32_t e = 0; e < count[n]; ++e) {
      key[first + e] = static_cast<std::uint32_t>(records[n * kTally + e].body_point);
      value[first + e] = static_cast<std::uint32_t>(n * kTally + e);
    }
  }
};
// Body point p's impulse: its entries added up in particle order, as the host adds them.
template <int D>
struct PointImpulse {
  const BodyImpulse<D>* records;
  const std::uint32_t* value;
  const std::uint32_t* start;
  Vec<D>* impulse;
  SLUICE_HOST_DEVICE void operator()(std::size_t p) const {
    Vec<D> sum = Vec<D>::Zero();
    for (std::uint32_t r = start[p]; r < start[p + 1]; ++r) sum += records[value[r]].impulse;
    impulse[p] = sum;
  }
};

// The step's results start from nothing.
template <int D>
struct ZeroResult {
  SolidStepResult<D>* results;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const { results[i] = SolidStepResult<D>{}; }
};

}  // namespace penalty_device

template <int D, class Backend>
class PenaltySphDeviceRunOn final
    : public ParticleDeviceServices<D, Backend, PenaltySphDeviceRun<D>> {
  template <class T>
  using Array = typename Backend::template Array<T>;
  using ParticleDeviceServices<D, Backend, PenaltySphDeviceRun<D>>::base_;
  using Scratch = BoundedDriftScratch<D>;
  using Totals = typename PenaltySphDeviceRun<D>::Totals;

 public:
  explicit PenaltySphDeviceRunOn(const PenaltySphDeviceSetup<D>& setup)
      : ParticleDeviceServices<D, Backend, PenaltySphDeviceRun<D>>(setup.base), setup_(setup) {
    const std::size_t points = setup.base.body_point_count;
    body_start_.resize(points);
    point_force_.resize(points);
    point_impulse_.resize(points);
    point_start_.resize(points + 1);
    std::uint32_t bits = 1;
    while ((std::size_t{1} << bits) <= points && bits < 32) ++bits;
    point_bits_ = static_cast<int>(bits);
  }

  // The base's and the fields' bytes, the run's own arrays per particle (the step's results,
  // the lists and their scan, the solids' copy), and the bodies' tallies per particle that
  // drifted with them at the last exchange.
  double bytes_per_particle() const override {
    const double n = static_cast<double>(base_.size());
    const double tallies = static_cast<double>(records_.size() * sizeof(BodyImpulse<D>) +
                                               3 * record_key_.size() * sizeof(std::uint32_t));
    return bytes_per_particle_ + (n > 0 ? tallies / n : 0);
  }

  void upload(const ParticleSet<D>& host, const std::vector<Vec3>& point_acceleration,
              const std::vector<std::uint32_t>& cell_start) override {
    base_.upload(host, point_acceleration, cell_start);
    const std::size_t n = base_.size();
    results_.resize(n);
    flag_.resize(n);
    counted_.resize(n);
    list_.resize(n);
    near_.resize(n);
    bytes_per_particle_ = ParticleDeviceRun<D, Backend>::bytes_per_particle(host) +
                          sizeof(SolidStepResult<D>) + 5 * sizeof(std::uint32_t) +
                          (2 * D + 2) * sizeof(Real) + sizeof(std::int32_t) +
                          (D * sizeof(Real) + 2 * sizeof(std::uint32_t));
  }

  void half_kick(Real dt) override { base_.for_each(PenaltyHalfKick<D>{arrays(), dt}); }
  void kick(Real dt) override { base_.for_each(PenaltyKick<D>{arrays(), dt}); }
  void density() override {
    base_.for_each(PenaltyDensity<D>{arrays(), setup_.constants, base_.cells()});
  }
  void forces() override {
    base_.for_each(PenaltyForces<D>{arrays(), setup_.constants, base_.cells()});
  }
  void body_pressure_forces(std::vector<Vec<D>>& force) override {
    base_.for_each(PenaltyBodyPressureForce<D>{arrays(), setup_.constants, base_.cells(),
                                               point_force_.data()});
    force.resize(point_force_.size());
    point_force_.to_host(force.data(), force.size());
  }
  Real max_speed() const override {
    const PenaltySphArrays<D> a = arrays();
    return base_.max_of(FluidVectorNorm<D>{a.kind, a.velocity});
  }
  Real max_acceleration() const override {
    const PenaltySphArrays<D> a = arrays();
    return base_.max_of(FluidVectorNorm<D>{a.kind, a.acceleration});
  }

  void gather_fixed_solids() override {
    const PenaltySphArrays<D> a = arrays();
    support_ = std::max<Real>(
        setup_.contact.kernels.h,
        base_.max_of(penalty_device::SolidReach<D>{a.kind, a.solid_spacing, setup_.fluid_spacing}));
    const std::size_t fixed =
        list(penalty_device::FixedSolidFlag{a.kind, a.body_point, flag_.data()}, list_);
    // A body point is one body particle.
    const std::size_t solids = fixed + setup_.base.body_point_count;
    solid_position_.resize(solids);
    solid_velocity_.resize(solids);
    solid_reach_.resize(solids);
    solid_volume_.resize(solids);
    solid_body_point_.resize(solids);
    fixed_count_ = 0;
    fixed_grid_ = place_solids(list_.data(), fixed, 0, nullptr, 0, fixed_cells_);
    fixed_count_ = fixed;
    moving_count_ = 0;
  }

  void start_drift(Real dt, bool with_bodies) override {
    base_.for_each(penalty_device::ZeroResult<D>{results_.data()});
    if (!with_bodies) return drift_all_fluid(dt);
    const PenaltySphArrays<D> a = arrays();
    // The bodies' particles in index order, which the last sort changed.
    bodies_ = list(penalty_device::BodyParticleFlag{a.body_point, flag_.data()}, body_list_);
    // The bodies' particles where they stand, and the fluid particles out of their reach over
    // the whole step (however fast either moves) drift at once.
    Backend::for_each(bodies_, penalty_device::BodyStart<D>{body_list_.data(), a.position,
                                                            a.body_point, body_start()});
    Vec<D> lo, hi;  // of the bodies' particles: where gather_moving(0) places them
    moving_grid_ = place_solids(body_list_.data(), bodies_, fixed_count_, body_start(), 0,
                                moving_cells_, &lo, &hi);
    moving_count_ = bodies_;
    const Real body_speed = std::max<Real>(
        0, bodies_ > 0 ? Backend::max_of(
                             bodies_, penalty_device::ListedSpeed<D>{body_list_.data(), a.velocity},
                             base_.workspace())
                       : 0);
    const PenaltyOutOfBodiesReach<D> out_of_reach{a.position, a.half_velocity, a.acceleration, lo,
                                                  hi,         body_speed,      support_,       dt};
    near_count_ =
        list(penalty_device::ReachFlag<D>{a.kind, out_of_reach, false, flag_.data()}, near_);
    const std::size_t far =
        list(penalty_device::ReachFlag<D>{a.kind, out_of_reach, true, flag_.data()}, list_);
    drift(list_.data(), far, dt, false);
  }

  void drift_with_bodies(Real dt, std::vector<Vec<D>>& impulse) override {
    gather_moving(dt);
    const std::size_t m = near_count_;
    records_.resize(m * Scratch::kTally);
    record_count_.resize(m);
    record_end_.resize(m);
    drift(near_.data(), m, dt, true);
    // The tallies' entries grouped by body point, in particle order within each (a stable
    // sort), then each point's added up in that order.
    std::uint32_t total = 0;
    if (m > 0) {
      Backend::inclusive_scan(record_count_.data(), record_end_.data(), m, base_.workspace());
      record_end_.to_host(&total, 1, m - 1);
    }
    record_key_.resize(total);
    record_value_.resize(total);
    Backend::for_each(m, penalty_device::TallyKeys<D, Scratch::kTally>{
                             records_.data(), record_count_.data(), record_end_.data(),
                             record_key_.data(), record_value_.data()});
    Backend::sort_by_key(record_key_, record_value_, total, point_bits_, base_.workspace());
    const std::size_t points = point_impulse_.size();
    Backend::for_each(points + 1,
                      device_bodies::CellStart{record_key_.data(), total, point_start_.data()});
    Backend::for_each(points,
                      penalty_device::PointImpulse<D>{records_.data(), record_value_.data(),
                                                      point_start_.data(), point_impulse_.data()});
    impulse.resize(points);
    point_impulse_.to_host(impulse.data(), points);
  }

  Totals finish_drift(Real dt) override {
    const PenaltySphArrays<D> a = arrays();
    base_.for_each(PenaltyEndOfDrift<D>{a.kind, a.half_velocity, a.acceleration, results_.data(),
                                        a.velocity, boundary_force(), dt});
    const std::size_t n = base_.size();
    const auto sum = [&](const auto& value) {
      return Backend::sum_of(n, value, base_.workspace());
    };
    const auto max = [&](const auto& value) { return base_.max_of(value); };
    return PenaltyStepCounters<D>{results_.data(), boundary_force()}.totals(sum, max);
  }

  double elastic_energy() const override {
    const PenaltySphArrays<D> a = arrays();
    return Backend::sum_of(
        base_.size(),
        PenaltyElasticEnergy<D>{a.kind, a.position, solids(), setup_.contact.law.stiffness},
        base_.workspace());
  }

 private:
  template <class T>
  static T* mutable_data(const Array<T>& a) {
    return const_cast<T*>(a.data());
  }
  template <class T>
  static Vec<D>* as_vectors(const Array<T>& a) {
    return reinterpret_cast<Vec<D>*>(mutable_data(a));
  }
  Vec<D>* body_start() { return body_start_.data(); }
  Vec<D>* boundary_force() const {
    return reinterpret_cast<Vec<D>*>(base_.particles().template components<Real>("boundary_force"));
  }

  // The device's particle fields as the loop bodies see them.
  PenaltySphArrays<D> arrays() const {
    static_assert(sizeof(Vec<D>) == D * sizeof(Real), "a vector is D reals in a row");
    const auto& set = base_.particles();
    auto reals = [&](const char* name) { return set.template components<Real>(name); };
    auto vectors = [&](const char* name) { return reinterpret_cast<Vec<D>*>(reals(name)); };
    auto integers = [&](const char* name) { return set.template components<std::int32_t>(name); };
    PenaltySphArrays<D> a;
    a.position = vectors("position");
    a.velocity = vectors("velocity");
    a.density = reals("density");
    a.pressure = reals("pressure");
    a.mass = reals("mass");
    a.kind = integers("kind");
    a.body_point = integers("body_point");
    a.solid_spacing = reals("solid_spacing");
    a.acceleration = vectors("acceleration");
    a.half_velocity = vectors("half_step_velocity");
    a.point_acceleration = base_.point_acceleration();
    return a;
  }
  SolidParticlesView<D> solids() const {
    SolidParticlesView<D> v;
    v.position = solid_position_.data();
    v.velocity = solid_velocity_.data();
    v.reach = solid_reach_.data();
    v.volume = solid_volume_.data();
    v.body_point = solid_body_point_.data();
    v.fixed_count = fixed_count_;
    v.count = fixed_count_ + moving_count_;
    v.fixed_grid = fixed_grid_;
    v.fixed_grid.cell_start = fixed_cells_.data();
    v.moving_grid = moving_grid_;
    v.moving_grid.cell_start = moving_cells_.data();
    v.support = support_;
    return v;
  }

  // The particles flagged by `flag` (which writes flag_) in index order, into `out`; their count.
  template <class Flag>
  std::size_t list(const Flag& flag, Array<std::uint32_t>& out) {
    const std::size_t n = base_.size();
    out.resize(n);
    if (n == 0) return 0;
    base_.for_each(flag);
    Backend::inclusive_scan(flag_.data(), counted_.data(), n, base_.workspace());
    std::uint32_t count = 0;
    counted_.to_host(&count, 1, n - 1);
    base_.for_each(penalty_device::Compact{flag_.data(), counted_.data(), out.data()});
    return count;
  }

  // The least and largest coordinates of x[n], n < count.
  void bounds(const Vec<D>* x, std::size_t count, Vec<D>& lo, Vec<D>& hi) {
    for (int axis = 0; axis < D; ++axis) {
      hi[axis] =
          Backend::max_of(count, penalty_device::Coordinate<D>{x, axis, 1}, base_.workspace());
      lo[axis] =
          -Backend::max_of(count, penalty_device::Coordinate<D>{x, axis, -1}, base_.workspace());
    }
  }

  // The listed solids from solid `offset` on, sorted by cell on a grid two supports wide over
  // where they start (SolidParticles::sorted_grid); the grid, with its cells in `cells`, and
  // into `lo` and `hi` where given the bounds of where they start.
  CellGridView<D> place_solids(const std::uint32_t* list, std::size_t count, std::size_t offset,
                               Vec<D>* start, Real dt, Array<std::uint32_t>& cells,
                               Vec<D>* bounds_lo = nullptr, Vec<D>* bounds_hi = nullptr) {
    if (count == 0) return {};
    const PenaltySphArrays<D> a = arrays();
    solid_x_.resize(count);
    Backend::for_each(count, penalty_device::SolidStart<D>{list, a.position, a.body_point, start,
                                                           solid_x_.data()});
    Vec<D> lo, hi;
    bounds(solid_x_.data(), count, lo, hi);
    if (bounds_lo) *bounds_lo = lo;
    if (bounds_hi) *bounds_hi = hi;
    std::size_t cell_count = 0;
    const CellGridView<D> grid = cell_grid_over<D>(lo, hi, 2 * support_, cell_count);
    solid_key_.resize(count);
    solid_order_.resize(count);
    Backend::for_each(count, penalty_device::SolidCell<D>{grid, solid_x_.data(), solid_key_.data(),
                                                          solid_order_.data()});
    std::uint32_t bits = 1;
    while ((std::size_t{1} << bits) <= cell_count && bits < 32) ++bits;
    Backend::sort_by_key(solid_key_, solid_order_, count, static_cast<int>(bits),
                         base_.workspace());
    Backend::for_each(
        count, penalty_device::PlaceSolid<D>{solid_order_.data(), list, solid_x_.data(), a.position,
                                             a.body_point, a.solid_spacing, setup_.fluid_spacing,
                                             dt, start, offset, as_vectors(solid_position_),
                                             as_vectors(solid_velocity_), solid_reach_.data(),
                                             solid_volume_.data(), solid_body_point_.data()});
    cells.resize(cell_count + 1);
    Backend::for_each(cell_count + 1,
                      device_bodies::CellStart{solid_key_.data(), count, cells.data()});
    return grid;
  }

  // The bodies' particles for a drift of dt (SolidParticles::gather_moving).
  void gather_moving(Real dt) {
    moving_grid_ =
        place_solids(body_list_.data(), bodies_, fixed_count_, body_start(), dt, moving_cells_);
    moving_count_ = bodies_;
  }

  // Every fluid particle drifts, in index order.
  void drift_all_fluid(Real dt) {
    const std::size_t fluid = list(device_bodies::FluidFlag{arrays().kind, flag_.data()}, list_);
    drift(list_.data(), fluid, dt, false);
  }

  // Drifts the `count` fluid particles of `which` by dt; with `on_bodies`, tallies their
  // impulses on the body points.
  void drift(const std::uint32_t* which, std::size_t count, Real dt, bool on_bodies) {
    const PenaltySphArrays<D> a = arrays();
    const PenaltyDriftArrays<D> d{a.position, a.half_velocity, a.mass, a.density, results_.data()};
    const Scratch scratch{on_bodies ? records_.data() : nullptr,
                          on_bodies ? record_count_.data() : nullptr};
    Backend::for_each(count,
                      PenaltyDrift<D, Scratch>{d, setup_.contact, solids(), which, dt, scratch});
    check_overflow();
  }

  void check_overflow() const {
    if (base_.max_of(typename PenaltyStepCounters<D>::Overflowed{results_.data()}) > 0) {
      // (No fmt here: this header is compiled by nvcc too, which fmt's headers do not pass.)
      throw std::runtime_error(
          "penalty-sph on the " + Backend::name() + " device: a fluid particle met more than " +
          std::to_string(Scratch::kCandidates) +
          " solid particles within two contact supports, or touched more than " +
          std::to_string(Scratch::kTally) +
          " body particles in one exchange: more than the device's lists hold; run this case "
          "with model.device: cpu");
    }
  }

  PenaltySphDeviceSetup<D> setup_;
  double bytes_per_particle_ = 0;
  Array<SolidStepResult<D>> results_;
  Array<std::uint32_t> flag_, counted_, list_, near_, body_list_;
  std::size_t near_count_ = 0, bodies_ = 0;
  // The solids (SolidParticlesView's arrays), their grids and the scratch that sorts them.
  Array<Vec<D>> solid_position_, solid_velocity_, solid_x_;
  Array<Real> solid_reach_, solid_volume_;
  Array<std::int32_t> solid_body_point_;
  Array<std::uint32_t> solid_key_, solid_order_, fixed_cells_, moving_cells_;
  CellGridView<D> fixed_grid_, moving_grid_;
  std::size_t fixed_count_ = 0, moving_count_ = 0;
  Real support_ = 0;
  // The bodies: each point's start of the drift, pressure force, and the drift's tallies and
  // their sum per point.
  Array<Vec<D>> body_start_, point_force_, point_impulse_;
  Array<BodyImpulse<D>> records_;
  Array<std::uint32_t> record_count_, record_end_, record_key_, record_value_, point_start_;
  int point_bits_ = 32;
};

}  // namespace sluice
