// Constraint fluids (seed 001's second method; Bodin, Lacoursière & Servin, IEEE TVCG 18(3),
// 2012): incompressibility as one constraint per particle, its kernel-summed density at most
// the rest density (density_constraints.hpp), met each step with the bodies' contacts and
// joints in one complementarity problem (this model joins the rigid system's velocity-level
// step as a participant: the monolithic coupling). Walls and bodies are particles in layers as
// thick as the kernel's support, with density constraints of their own where fluid is near;
// so the walls push with a pressure of their own, and a body feels the impulses of its
// particles' rows and of the fluid rows whose density its particles raise. Each step the fluid
// particles take gravity, the solve gives the impulses and the velocities, and they move with
// them. A particle's pressure is its row's impulse per unit volume and time, dx gamma / (h V),
// the SPH pressure that the same force would take, times the lattice's gradient moment
// V sum x^2 |F| (0.97 at h = 1.3 dx: the kernel gradient's shortfall on a lattice, which the
// pressure makes up in hydrostatic balance). The rest density is the kernel's sum over the full
// lattice of the spacing, so that the fluid as built meets its constraints.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "sluice/ccp/spook.hpp"
#include "sluice/exec/policy.hpp"
#include "sluice/fluid/constraint/constraint_parameters.hpp"
#include "sluice/fluid/constraint/density_constraints.hpp"
#include "sluice/fluid/constraint/density_row_build.hpp"
#include "sluice/fluid/constraint/device_constraint_groups.hpp"
#include "sluice/fluid/constraint/viscosity_constraints.hpp"
#include "sluice/fluid/flat_wall_share.hpp"
#include "sluice/fluid/monolithic_case.hpp"
#include "sluice/fluid/monolithic_solve.hpp"
#include "sluice/fluid/particle_fluid.hpp"
#include "sluice/kernels/wendland_c2.hpp"

namespace sluice {

template <int D>
class ConstraintModel final : public ParticleFluid<D> {
 public:
  ConstraintModel(const ConstraintParameters& parameters, const io::CaseConfig& config,
                  const BodyGeometry& bodies)
      : ParticleFluid<D>(config, 2 * parameters.h_over_dx * config.spacing, bodies),
        p_(parameters),
        bodies_(&bodies),
        kernel_(parameters.h_over_dx * config.spacing),
        dx_(config.spacing),
        rho0_(config.fluid.density),
        mass_(config.fluid.density * std::pow(config.spacing, D)),
        volume_(std::pow(config.spacing, D)),
        rest_sum_(lattice_sum([this](Real r, Real) { return mass_ * kernel_.value(r); })),
        // V sum x^2 (-F(r)) over the lattice: 1 for an exact kernel gradient.
        gradient_moment_(volume_ * lattice_sum([this](Real r, Real x) {
                           return -x * x * kernel_.gradient_factor(r);
                         })),
        solve_(parameters.emulated_device, add_constraint_group_copiers<exec::HostBackend>) {}

  std::string describe() const override {
    return fmt::format(
        "constraint: wendland h = {:.4g} m ({} dx), {} density constraints, compliance {:.3g} "
        "1/Pa (bulk modulus {:.3g} Pa), relaxation {} steps, {}, {}, solve to {} m/s in at most "
        "{} iterations{}",
        kernel_.h, p_.h_over_dx, p_.unilateral ? "unilateral" : "bilateral", p_.compliance,
        1 / p_.compliance, p_.relaxation,
        p_.viscosity > 0 ? fmt::format("viscosity constraints of {} m^2/s", p_.viscosity)
                         : "no viscosity constraints",
        p_.time_step > 0 ? fmt::format("fixed dt = {} s", p_.time_step)
                         : fmt::format("dt = {} dx / max speed", p_.cfl),
        p_.tolerance, p_.max_iterations, p_.emulated_device ? ", " + solve_.where() : "");
  }

  void initialize() override {
    viscous_force_ = this->state().particles.add_vector_field({"viscous_force", "N"});
    find_body_point_shares();
    build_rows();
  }

  TimeStep next_time_step() const override {
    TimeStep step;
    if (p_.time_step > 0) {
      step.tighten(p_.time_step, "model.time_step");
    } else {
      step.tighten(p_.cfl * dx_ / std::max(max_speed_, 0.1 * p_.max_speed),
                   "the flow speed (or a tenth of model.max_speed)");
    }
    return step;
  }

  // The fluid particles as bodies after the rigid ones, with gravity in their predicted
  // velocity, and the density rows with their SPOOK targets, compliance and warm start.
  void add_to_problem(CcpProblem& problem, double h) override {
    const auto& ps = this->state().particles;
    // The rigid system's bodies come first, the case's in their order (then its fixed ones).
    const std::size_t first = first_ = problem.bodies.size();
    rows_.place(first);
    viscosity_.place(first);
    const Vec3 gravity = to_3d<D>(this->state().gravity);
    const std::uint8_t locks = D == 2 ? kLockPlanar : 0;
    const std::size_t fluid = rows_.fluid_rows();
    // The rows' rates at the step's start: the bodies' velocities before the step.
    BodyVelocities start;
    start.linear.assign(first + fluid, Vec3::Zero());
    start.angular.assign(first + fluid, Vec3::Zero());
    // The case's bodies; the walls' contact bodies after them stand still.
    const std::vector<BodyKinematics> motion = bodies_->motion();
    for (std::size_t b = 0; b < std::min(first, motion.size()); ++b) {
      start.linear[b] = motion[b].velocity;
      start.angular[b] = motion[b].angular_velocity;
    }
    for (std::size_t j = 0; j < fluid; ++j) {
      const Vec3 v = to_3d<D>(ps.velocity[row_particle_[j]]);
      start.linear[first + j] = v;
      problem.bodies.add(v + h * gravity, Vec3::Zero(), 1 / mass_, 0.0, locks);
    }
    const std::size_t rows = rows_.size();
    std::fill(rows_.target().begin(), rows_.target().end(), 0.0);
    std::vector<Real> rate(rows);
    rows_.row_velocities(start, rate);
    const SpookStep spook(h, p_.relaxation);
    // The compliance of c = dx (1 - rho / rho_ref): dx^2 / (K V), K the bulk modulus.
    const Real compliance = spook.compliance * dx_ * dx_ * p_.compliance / volume_;
    exec::Default::for_each_light(rows, [&](std::size_t r) {
      rows_.target()[r] = spook.target(rows_.constraint(r), rate[r]);
      rows_.compliance()[r] = compliance;
      // The last step's pressure, as an impulse over this step.
      const Real warm = ps.pressure[row_particle_[r]] * h * volume_ / (dx_ * gradient_moment_);
      rows_.impulse()[r] = p_.unilateral ? std::max<Real>(warm, 0) : warm;
    });
    problem.add(rows_);
    if (p_.viscosity > 0) {
      // beta = 2 (D + 2) nu / h_k^2; compliance 1 / (h m beta).
      const Real beta = 2 * (D + 2) * p_.viscosity / (kernel_.h * kernel_.h);
      viscosity_.set_compliance(1 / (h * mass_ * beta));
      const auto& force = ps[viscous_force_];
      for (std::size_t j = 0; j < fluid; ++j) {
        for (int a = 0; a < D; ++a)
          viscosity_.impulse()[j * D + a] = h * force[row_particle_[j]][a];
      }
      problem.add(viscosity_);
    }
  }

  CcpResult solve(CcpProblem& problem, const CcpSettings& settings,
                  BodyVelocities& velocities) override {
    return solve_(problem, settings, velocities);
  }

  void take_solution(const CcpProblem&, const BodyVelocities& u, double h) override {
    auto& ps = this->state().particles;
    const std::size_t first = first_;
    const std::size_t fluid = rows_.fluid_rows();
    exec::Default::for_each(fluid, [&](std::size_t j) {
      const std::size_t i = row_particle_[j];
      ps.velocity[i] = from_3d<D>(u.linear[first + j]);
      ps.position[i] += h * ps.velocity[i];
    });
    exec::Default::for_each(ps.size(), [&](std::size_t i) {
      if (!ps.is_fluid(i)) ps.pressure[i] = 0;
    });
    if (p_.viscosity > 0) {
      auto& force = ps[viscous_force_];
      for (std::size_t j = 0; j < fluid; ++j) {
        for (int a = 0; a < D; ++a)
          force[row_particle_[j]][a] = viscosity_.impulse()[j * D + a] / h;
      }
    }
    const std::vector<Real>& gamma = rows_.impulse();
    exec::Default::for_each(rows_.size(), [&](std::size_t r) {
      ps.pressure[row_particle_[r]] = gradient_moment_ * dx_ * gamma[r] / (h * volume_);
    });
    body_load_.assign(bodies_->body_count(), Wrench{});
    for (const auto& e : rows_.body_entries()) {
      body_load_[e.body].force += gamma[e.row] / h * e.linear;
      body_load_[e.body].moment += gamma[e.row] / h * e.angular;
    }
    max_speed_ = exec::Default::max_of(
        fluid, [&](std::size_t j) { return ps.velocity[row_particle_[j]].norm(); });
    ++steps_;
  }

  std::vector<Wrench> body_loads(const std::vector<BodyKinematics>& motion) const override {
    return loads_of_solve(body_load_, motion.size());
  }

  std::vector<std::pair<std::string, double>> counters() const override {
    const double steps = std::max<double>(1, double(steps_));
    std::vector<std::pair<std::string, double>> out{
        {"largest_density_error", largest_error_},
        {"rows_per_step", double(row_total_) / steps},
        {"neighbours_per_row", double(entry_total_) / std::max<double>(1, double(row_total_))}};
    // The device's copy of the problem, per particle of the set (walls and bodies' too).
    if (solve_.on_device()) {
      out.emplace_back("device_bytes_per_particle",
                       double(solve_.largest_bytes()) /
                           std::max<double>(1, double(this->state().particles.size())));
    }
    return out;
  }

  // The largest compression of a fluid particle, rho / rho_ref - 1, now and over the run.
  Real density_error() const { return density_error_; }
  Real largest_density_error() const { return largest_error_; }
  const DensityConstraints& rows() const { return rows_; }
  const ViscosityConstraints& viscosity_rows() const { return viscosity_; }
  // The row's particle.
  std::size_t row_particle(std::size_t r) const { return row_particle_[r]; }

 protected:
  void model_stages(StageList&, StageList& after) override {
    after.push_back(
        make_stage<const StepClock>("density_rows", [this](const StepClock&) { build_rows(); }));
  }
  // The rows the next solve takes were built at the end of the last step from what the
  // checkpoint holds: read back, they are built again, and the running totals that building
  // adds to are put back as they were.
  void archive_model(StateArchive& a) override {
    a(max_speed_, steps_, largest_error_, row_total_, entry_total_);
    if (!a.reading()) return;
    const Real largest = largest_error_;
    const long rows = row_total_, entries = entry_total_;
    build_rows();
    largest_error_ = largest;
    row_total_ = rows;
    entry_total_ = entries;
  }
  // The loads come from the solve (body_loads), not from the body particles.
  void body_point_forces(const std::vector<BodyKinematics>&, std::vector<Vec3>&) const override {}

 private:
  static constexpr std::uint32_t kNoRow = kNoDensityRow;
  static constexpr std::size_t kBlock = 1024;

  // A block's fluid rows' neighbours for the viscosity constraints (kernel values).
  struct ViscousBlock {
    std::vector<ViscosityConstraints::Entry> entries;
    std::vector<std::uint32_t> counts;
    void clear() {
      entries.clear();
      counts.clear();
    }
  };

  // The sum of f(r, x) over a full lattice of the spacing about one of its points, at each
  // point's distance r and first coordinate x.
  template <class F>
  Real lattice_sum(F&& f) const {
    const int reach = static_cast<int>(std::ceil(kernel_.support() / dx_));
    Real sum = 0;
    int n[3] = {0, 0, 0};
    for (n[0] = -reach; n[0] <= reach; ++n[0]) {
      for (n[1] = -reach; n[1] <= reach; ++n[1]) {
        for (n[2] = D == 3 ? -reach : 0; n[2] <= (D == 3 ? reach : 0); ++n[2]) {
          const Real r = dx_ * std::sqrt(Real(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]));
          if (r < kernel_.support()) sum += f(r, dx_ * n[0]);
        }
      }
    }
    return sum;
  }

 public:
  // The rows for the particles as they stand: the fluid particles, then the wall particles and
  // the bodies' outer-layer particles with fluid in reach (NearFluid); each row's neighbours,
  // Jacobian and constraint value, and each row particle's density (rho0 times its share of the
  // rest sum). The model's stage after the neighbour sort (public for the tests of the Jacobian).
  void build_rows() {
    auto& ps = this->state().particles;
    const auto& cells = this->state().cells;
    const Real support2 = kernel_.support() * kernel_.support();
    row_of_.assign(ps.size(), kNoRow);
    row_particle_.clear();
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (!ps.is_fluid(i)) continue;
      row_of_[i] = static_cast<std::uint32_t>(row_particle_.size());
      row_particle_.push_back(static_cast<std::uint32_t>(i));
    }
    const std::size_t fluid = row_particle_.size();
    std::vector<char> near_fluid(ps.size());
    exec::Default::for_each(
        ps.size(),
        NearFluid<D>{cells.view(), ps.position.data(), ps.kind.data(), ps.body_point.data(),
                     outer_point_.data(), support2, near_fluid.data()});
    for (std::size_t i = 0; i < ps.size(); ++i) {
      if (!near_fluid[i]) continue;
      row_of_[i] = static_cast<std::uint32_t>(row_particle_.size());
      row_particle_.push_back(static_cast<std::uint32_t>(i));
    }
    std::vector<Vec3> body_centre;
    for (const BodyKinematics& m : bodies_->motion()) body_centre.push_back(m.position);
    const DensityRowInput<D> input = row_input(body_centre);
    const std::size_t blocks = (row_particle_.size() + kBlock - 1) / kBlock;
    blocks_.resize(blocks);
    viscous_blocks_.resize(blocks);
    std::vector<Real> errors(blocks, 0);
    exec::Default::for_each_balanced(blocks, [&](std::size_t k) {
      DensityConstraints::Block& block = blocks_[k];
      block.clear();
      viscous_blocks_[k].clear();
      const std::size_t end = std::min(row_particle_.size(), (k + 1) * kBlock);
      for (std::size_t r = k * kBlock; r < end; ++r) {
        const Real ratio = add_row(std::uint32_t(r), input, block, viscous_blocks_[k]);
        if (r < fluid) errors[k] = std::max(errors[k], ratio - 1);
      }
    });
    rows_.begin(fluid, 1 / mass_, p_.unilateral);
    for (const auto& block : blocks_) rows_.append(block);
    if (p_.viscosity > 0) {
      viscosity_.begin(fluid, 1 / mass_,
                       D == 2 ? std::vector<int>{0, 2} : std::vector<int>{0, 1, 2});
      auto& entries = viscosity_.entries();
      std::size_t j = 0;
      for (const auto& block : viscous_blocks_) {
        for (const std::uint32_t count : block.counts) {
          if (j >= fluid) break;
          viscosity_.offsets()[j + 1] = viscosity_.offsets()[j] + count;
          ++j;
        }
        entries.insert(entries.end(), block.entries.begin(), block.entries.end());
      }
      viscosity_.normalise();
    }
    density_error_ = blocks == 0 ? 0 : *std::max_element(errors.begin(), errors.end());
    largest_error_ = std::max(largest_error_, density_error_);
    row_total_ += rows_.size();
    entry_total_ += rows_.entry_count();
  }

 private:
  // Row r into the block (density_row_build.hpp); returns rho_r / rho_ref.
  Real add_row(std::uint32_t r, const DensityRowInput<D>& input, DensityConstraints::Block& block,
               ViscousBlock& viscous) {
    // The block's entries as the row finds them; a body's parts added into one entry.
    struct BlockSink {
      DensityConstraints::Block& block;
      ViscousBlock& viscous_block;
      std::uint32_t r;
      std::size_t first_body;
      std::uint32_t entries = 0, viscous_entries = 0;
      void entry(std::uint32_t row, const Vec3& q) {
        block.entries.push_back({row, q});
        ++entries;
      }
      void viscous(std::uint32_t row, Real w) {
        viscous_block.entries.push_back({row, w, 0});
        ++viscous_entries;
      }
      void body(std::uint32_t b, const Vec3& linear, const Vec3& angular) {
        add_body_entry(block, first_body, r, b, linear, angular);
      }
    } sink{block, viscous, r, block.bodies.size()};
    auto& ps = this->state().particles;
    const std::size_t i = row_particle_[r];
    const DensityRowValues row = build_density_row(input, r, sink);
    block.entry_counts.push_back(sink.entries);
    if (ps.is_fluid(i)) viscous.counts.push_back(sink.viscous_entries);
    block.body_counts.push_back(std::uint32_t(block.bodies.size() - sink.first_body));
    block.sigma.push_back(row.sigma);
    block.c.push_back(row.c);
    ps.density[i] = rho0_ * row.ratio;
    return row.ratio;
  }

  // What the rows are built from (density_row_build.hpp), for the bodies' present centres.
  DensityRowInput<D> row_input(const std::vector<Vec3>& body_centre) const {
    const auto& ps = this->state().particles;
    return {this->state().cells.view(),
            ps.position.data(),
            ps.kind.data(),
            ps.body_point.data(),
            point_body_.data(),
            body_point_share_.data(),
            body_centre.data(),
            row_of_.data(),
            row_particle_.data(),
            kernel_,
            mass_,
            rest_sum_,
            dx_};
  }

  // For each body point, what a particle at its depth in a flat lattice wall of as many layers
  // as the body's sums from its own wall (flat_wall_share.hpp), and its body.
  void find_body_point_shares() {
    const int layers = wall_layers(kernel_.support(), dx_);
    const auto w = [this](Real r) { return mass_ * kernel_.value(r); };
    const std::vector<int> layer = body_point_layers(*bodies_, this->body_points(), dx_, layers);
    body_point_share_.resize(layer.size());
    point_body_.resize(layer.size());
    outer_point_.resize(layer.size());
    for (std::size_t k = 0; k < layer.size(); ++k) {
      body_point_share_[k] = flat_wall_sum<D>(w, kernel_.support(), dx_, layers, layer[k]);
      point_body_[k] = std::uint32_t(this->body_points()[k].body);
      outer_point_[k] = layer[k] == 0;
    }
  }

  // Adds (linear, angular) to row r's entry for `body` among the row's entries from `from`.
  static void add_body_entry(DensityConstraints::Block& block, std::size_t from, std::uint32_t r,
                             std::uint32_t body, const Vec3& linear, const Vec3& angular) {
    for (std::size_t k = from; k < block.bodies.size(); ++k) {
      if (block.bodies[k].body != body) continue;
      block.bodies[k].linear += linear;
      block.bodies[k].angular += angular;
      return;
    }
    block.bodies.push_back({r, body, linear, angular});
  }

  ConstraintParameters p_;
  const BodyGeometry* bodies_;
  WendlandC2<D> kernel_;
  Real dx_, rho0_, mass_, volume_, rest_sum_, gradient_moment_;
  DensityConstraints rows_;
  std::vector<DensityConstraints::Block> blocks_;
  ViscosityConstraints viscosity_;
  std::vector<ViscousBlock> viscous_blocks_;
  FieldHandle<Vec<D>> viscous_force_;
  std::vector<std::uint32_t> row_of_;        // particle -> row (kNoRow: none)
  std::vector<std::uint32_t> row_particle_;  // row -> particle
  std::vector<Wrench> body_load_;
  std::vector<Real> body_point_share_;     // find_body_point_shares
  std::vector<std::uint32_t> point_body_;  // each body point's body
  std::vector<char> outer_point_;          // each body point: 1 in its body's outer layer
  std::size_t first_ = 0;                  // the fluid particles' first body in the problem
  Real max_speed_ = 0;
  Real density_error_ = 0, largest_error_ = 0;
  long steps_ = 0, row_total_ = 0, entry_total_ = 0;
  MonolithicSolve solve_;
};

}  // namespace sluice
