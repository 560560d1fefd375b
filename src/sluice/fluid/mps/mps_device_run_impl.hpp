// The device run of mps_device_run.hpp: the particle base's services on the device
// (particle_device_run.hpp, which describes what a backend offers) and mps's own stages, the
// loop bodies the host runs (mps_loop_bodies.hpp, pressure_rows.hpp) over the
// device's arrays. Included by mps_device_run.cpp (the host's threads, the emulated device).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sluice/fluid/fluid_vector_norm.hpp"
#include "sluice/fluid/mps/mps_device_run.hpp"
#include "sluice/fluid/mps/mps_loop_bodies.hpp"
#include "sluice/fluid/mps/neighbour_view.hpp"
#include "sluice/fluid/mps/pressure_rows.hpp"
#include "sluice/fluid/particle_device_run.hpp"
#include "sluice/linear/sparse_solver.hpp"

namespace sluice {

// The neighbour list's rows: first each row's count, then, from the counts' scan, its entries.
template <int D>
struct MpsNeighbourCount {
  MpsListed<D> listed;
  const Vec<D>* position;
  Real radius2;
  std::uint32_t* count;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    std::uint32_t n = 0;
    if (listed(i))
      for_each_neighbour_within(listed.cells, position, i, radius2, [&](std::uint32_t) { ++n; });
    count[i] = n;
  }
};
template <int D>
struct MpsNeighbourFill {
  CellGridView<D> cells;
  const Vec<D>* position;
  Real radius2;
  const std::uint32_t* start;
  std::uint32_t* index;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    std::uint32_t k = start[i];
    if (start[i + 1] == k) return;
    for_each_neighbour_within(cells, position, i, radius2,
                              [&](std::uint32_t j) { index[k++] = j; });
  }
};

// The pressure equation's unknowns, numbered in particle order: whether particle i is one,
// then from the flags' scan its row and the row's particle.
template <int D>
struct PressureUnknownFlag {
  PressureEquationInputs<D> in;
  std::uint32_t* flag;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const { flag[i] = in.unknown(i) ? 1u : 0u; }
};
struct PressureNumbering {
  const std::uint32_t* flag;
  const std::uint32_t* counted;  // the flags' inclusive scan
  int* row_of;
  std::size_t* particle_of;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    if (!flag[i]) {
      row_of[i] = -1;
      return;
    }
    const std::uint32_t r = counted[i] - 1;
    row_of[i] = static_cast<int>(r);
    particle_of[r] = i;
  }
};

// The solve's first guess from the last pressure, and its answer back into the pressure.
struct PressureGuess {
  const Real* pressure;
  const std::size_t* particle_of;
  Real* guess;
  SLUICE_HOST_DEVICE void operator()(std::size_t r) const { guess[r] = pressure[particle_of[r]]; }
};
struct PressureAnswer {
  const Real* solution;
  const int* row_of;
  Real* pressure;
  SLUICE_HOST_DEVICE void operator()(std::size_t i) const {
    pressure[i] = row_of[i] >= 0 ? solution[row_of[i]] : 0;
  }
};

template <int D, class Backend>
class MpsDeviceRunOn final : public ParticleDeviceServices<D, Backend, MpsDeviceRun<D>> {
  template <class T>
  using Array = typename Backend::template Array<T>;
  using ParticleDeviceServices<D, Backend, MpsDeviceRun<D>>::base_;

 public:
  explicit MpsDeviceRunOn(const MpsDeviceSetup<D>& setup)
      : ParticleDeviceServices<D, Backend, MpsDeviceRun<D>>(setup.base),
        setup_(setup),
        solver_(make_sparse_solver(setup.solver, setup.solver_settings)) {
    if (!solver_) throw std::invalid_argument("unknown sparse solver " + setup.solver);
  }

  // The base's and the fields' bytes, the run's own arrays per particle (the activity, the
  // scratch velocity, the extrapolated walls' inputs, the list's counts and starts, the
  // numbering), and per neighbour in the present list its index and at most one entry of the
  // pressure's rows (a column and a value): in 3D about as much again as the rest.
  double bytes_per_particle() const override {
    const double n = static_cast<double>(base_.size());
    const double per_neighbour = sizeof(std::uint32_t) + sizeof(int) + sizeof(Real);
    return bytes_per_particle_ +
           (n > 0 ? per_neighbour * static_cast<double>(index_.size()) / n : 0);
  }

  void upload(const ParticleSet<D>& host, const std::vector<Vec3>& point_acceleration,
              const std::vector<std::uint32_t>& cell_start) override {
    base_.upload(host, point_acceleration, cell_start);
    const std::size_t n = base_.size();
    active_.resize(n);
    scratch_.resize(D * n);
    extrapolated_.resize(n);
    wall_gravity_.resize(D * n);
    source_velocity_.resize(D * n);
    count_.resize(n);
    start_.resize(n + 1);
    flag_.resize(n);
    counted_.resize(n);
    row_of_.resize(n);
    particle_of_.resize(n);
    const std::uint32_t zero = 0;
    start_.from_host(&zero, 1);
    bytes_per_particle_ = ParticleDeviceRun<D, Backend>::bytes_per_particle(host) + 1 +
                          3 * D * sizeof(Real) + 1 + 4 * sizeof(std::uint32_t) + sizeof(int) +
                          sizeof(std::size_t);
  }

  void predict(Real dt, Real nu) override {
    const MpsArrays<D> a = arrays();
    base_.for_each(MpsPrediction<D>{a, operators(), setup_.gravity, nu, dt});
    base_.for_each(MpsTakeVelocity<D>{a, dt});
    if (setup_.collision_reach <= 0) return;
    const Real reach2 = setup_.collision_reach * setup_.collision_reach;
    base_.for_each(MpsCollision<D>{a, neighbour_view(), reach2, setup_.collision_restitution});
    base_.for_each(MpsAddVelocity<D>{a, dt});
  }

  void build_neighbours() override {
    const MpsArrays<D> a = arrays();
    const std::size_t n = base_.size();
    const CellGridView<D> cells = base_.cells();
    const Real radius2 = setup_.neighbour_radius * setup_.neighbour_radius;
    const MpsListed<D> listed{a.role, a.position->data(), cells, base_.fluid_before(),
                              setup_.extrapolated_walls};
    base_.for_each(MpsNeighbourCount<D>{listed, a.position, radius2, count_.data()});
    Backend::inclusive_scan(count_.data(), start_.data() + 1, n, base_.workspace());
    std::uint32_t entries = 0;
    start_.to_host(&entries, 1, n);
    index_.resize(entries);
    base_.for_each(MpsNeighbourFill<D>{cells, a.position, radius2, start_.data(), index_.data()});
  }

  void find_surface() override {
    base_.for_each(MpsNumberDensity<D>{arrays(), operators(), setup_.surface_density,
                                       setup_.surface_count, setup_.extrapolated_walls});
  }

  void state_equation(Real stiffness) override {
    base_.for_each(MpsStateEquation<D>{arrays(), stiffness, setup_.lattice.n0});
  }

  void assemble(Real dt, Real relaxation, Real compressibility, bool pressure_memory) override {
    const std::size_t n = base_.size();
    const MpsArrays<D> a = arrays();
    if (setup_.extrapolated_walls) {
      base_.for_each(MpsWallInputs<D>{a, base_.point_acceleration(), setup_.gravity, dt,
                                      extrapolated_.data(), wall_gravity(), source_velocity()});
    }
    PressureEquationInputs<D> in{
        operators(),      n,         setup_.extrapolated_walls ? source_velocity() : a.velocity,
        a.number_density, a.surface, a.active,
        a.pressure};
    in.dt = dt;
    in.density = setup_.density;
    if (setup_.extrapolated_walls) {
      in.extrapolated = extrapolated_.data();
      in.wall_gravity = wall_gravity();
    }
    // The unknowns, in particle order.
    base_.for_each(PressureUnknownFlag<D>{in, flag_.data()});
    Backend::inclusive_scan(flag_.data(), counted_.data(), n, base_.workspace());
    std::uint32_t unknowns = 0;
    if (n > 0) counted_.to_host(&unknowns, 1, n - 1);
    base_.for_each(
        PressureNumbering{flag_.data(), counted_.data(), row_of_.data(), particle_of_.data()});
    unknowns_ = unknowns;
    // Pass 1: entries per row; pass 2: the values and the right-hand side.
    row_count_.resize(unknowns + 1);
    row_start_.resize(unknowns + 1);
    const int zero = 0;
    row_start_.from_host(&zero, 1);
    Backend::for_each(
        unknowns, PressureRowCount<D>{in, row_of_.data(), particle_of_.data(), row_count_.data()});
    Backend::inclusive_scan(reinterpret_cast<const std::uint32_t*>(row_count_.data()) + 1,
                            reinterpret_cast<std::uint32_t*>(row_start_.data()) + 1, unknowns,
                            base_.workspace());
    int entries = 0;
    row_start_.to_host(&entries, 1, unknowns);
    column_.resize(static_cast<std::size_t>(entries));
    value_.resize(static_cast<std::size_t>(entries));
    rhs_.resize(unknowns);
    const Real inverse_dt = 1 / dt;
    const Real alpha = compressibility * setup_.density * inverse_dt * inverse_dt;
    Backend::for_each(
        unknowns, PressureRowValues<D>{in, row_of_.data(), particle_of_.data(), row_start_.data(),
                                       column_.data(), value_.data(), rhs_.data(),
                                       relaxation * setup_.density * inverse_dt * inverse_dt,
                                       (1 - relaxation) * setup_.density * inverse_dt, alpha,
                                       pressure_memory ? (1 - relaxation) * alpha : 0});
    report_ = PressureEquationReport{};
    report_.unknowns = unknowns;
    report_.entries = static_cast<std::size_t>(entries);
  }

  // The host's solver on the rows copied into its matrix, from the last pressure.
  bool solve() override {
    const std::size_t unknowns = unknowns_;
    const auto u = static_cast<Eigen::Index>(unknowns);
    guess_array_.resize(unknowns);
    const MpsArrays<D> a = arrays();
    Backend::for_each(unknowns,
                      PressureGuess{a.pressure, particle_of_.data(), guess_array_.data()});
    SolveReport solved;
    solved.converged = true;
    if (unknowns > 0) {
      matrix_.resize(u, u);
      row_start_.to_host(matrix_.outerIndexPtr(), unknowns + 1);
      matrix_.resizeNonZeros(static_cast<Eigen::Index>(report_.entries));
      column_.to_host(matrix_.innerIndexPtr(), report_.entries);
      value_.to_host(matrix_.valuePtr(), report_.entries);
      rhs_vector_.resize(u);
      rhs_.to_host(rhs_vector_.data(), unknowns);
      guess_.resize(u);
      guess_array_.to_host(guess_.data(), unknowns);
      solved = solver_->solve(matrix_, rhs_vector_, guess_);
      guess_array_.from_host(guess_.data(), unknowns);
    }
    report_.iterations = solved.iterations;
    report_.relative_residual = solved.relative_residual;
    report_.converged = solved.converged;
    base_.for_each(PressureAnswer{guess_array_.data(), row_of_.data(), a.pressure});
    return solved.converged;
  }
  const PressureEquationReport& report() const override { return report_; }

  void clamp_negative() override { base_.for_each(MpsClampPressure<D>{arrays()}); }

  void correct(Real dt) override {
    const MpsArrays<D> a = arrays();
    base_.for_each(
        MpsPressureCorrection<D>{a, operators(), dt / setup_.density, setup_.minimum_density});
    base_.for_each(MpsAddVelocity<D>{a, dt});
  }

  Real max_speed() const override {
    const MpsArrays<D> a = arrays();
    return base_.max_of(FluidVectorNorm<D>{a.kind, a.velocity});
  }

  void download_active(std::vector<std::uint8_t>& active) const override {
    active.resize(base_.size());
    active_.to_host(active.data(), active.size());
  }
  void download_neighbours(std::vector<std::uint32_t>& start,
                           std::vector<std::uint32_t>& index) const override {
    start.resize(start_.size());
    start_.to_host(start.data(), start.size());
    index.resize(index_.size());
    index_.to_host(index.data(), index.size());
  }
  void upload_neighbours(const std::vector<std::uint32_t>& start,
                         const std::vector<std::uint32_t>& index) override {
    start_.resize(start.size());
    start_.from_host(start.data(), start.size());
    index_.resize(index.size());
    index_.from_host(index.data(), index.size());
  }

 private:
  template <class T>
  static T* mutable_data(const Array<T>& a) {
    return const_cast<T*>(a.data());
  }
  Vec<D>* as_vectors(const Array<Real>& a) const {
    return reinterpret_cast<Vec<D>*>(mutable_data(a));
  }
  Vec<D>* wall_gravity() const { return as_vectors(wall_gravity_); }
  Vec<D>* source_velocity() const { return as_vectors(source_velocity_); }

  // The device's particle fields and the run's own arrays, as the loop bodies see them.
  MpsArrays<D> arrays() const {
    static_assert(sizeof(Vec<D>) == D * sizeof(Real), "a vector is D reals in a row");
    const auto& set = base_.particles();
    auto reals = [&](const char* name) { return set.template components<Real>(name); };
    auto integers = [&](const char* name) { return set.template components<std::int32_t>(name); };
    MpsArrays<D> a;
    a.position = reinterpret_cast<Vec<D>*>(reals("position"));
    a.velocity = reinterpret_cast<Vec<D>*>(reals("velocity"));
    a.pressure = reals("pressure");
    a.kind = integers("kind");
    a.body_point = integers("body_point");
    a.role = integers("mps_role");
    a.number_density = reals("number_density");
    a.surface = integers("free_surface");
    a.active = mutable_data(active_);
    a.scratch = as_vectors(scratch_);
    return a;
  }
  NeighbourView neighbour_view() const { return {start_.data(), index_.data()}; }
  MpsOperators<D> operators() const {
    return MpsOperators<D>(arrays().position, neighbour_view(), setup_.weight, setup_.lattice,
                           setup_.laplacian_weight, setup_.laplacian_lattice,
                           setup_.gradient_correction);
  }

  MpsDeviceSetup<D> setup_;
  std::unique_ptr<SparseSolver> solver_;
  double bytes_per_particle_ = 0;
  Array<std::uint8_t> active_, extrapolated_;
  Array<Real> scratch_, wall_gravity_, source_velocity_;
  Array<std::uint32_t> count_, start_, index_, flag_, counted_;
  Array<int> row_of_, row_count_, row_start_, column_;
  Array<std::size_t> particle_of_;
  Array<Real> value_, rhs_, guess_array_;
  std::size_t unknowns_ = 0;
  PressureEquationReport report_;
  SparseRows matrix_;  // the host solver's copy of the rows
  Eigen::VectorXd rhs_vector_, guess_;
};

}  // namespace sluice
