// A cone complementarity problem (ccp_problem.hpp) copied to a device, and solved there by the
// solvers of ccp_iterations.hpp: the bodies and every group live in the device's memory for the
// solve, since each iteration touches all of them (two products with N), and only the warm
// start goes over at the start and the impulses and the bodies' velocities come back at the end.
// Each kind of group has a copy of its own on the device (DeviceCcpGroup) running the loop
// bodies its host class runs, in the same order, so that on the emulated device
// (exec/host_backend.hpp) the solve is the host's to the bit. Over a backend as
// particle_device_run.hpp describes, with block_sum_of for the solvers' sums.
#pragma once

#include <functional>
#include <memory>
#include <stdexcept>
#include <vector>

#include "sluice/ccp/ccp_iterations.hpp"
#include "sluice/ccp/ccp_problem.hpp"
#include "sluice/exec/array_copies.hpp"

namespace sluice {

// The bodies on the device: their predicted velocities v*, M^-1, and the velocities u after the
// impulses of the last gradient.
template <class Backend>
struct DeviceCcpBodies {
  template <class T>
  using Array = typename Backend::template Array<T>;

  Array<Vec3> predicted_linear, predicted_angular, linear, angular;
  Array<Real> inverse_mass, inverse_inertia_scalar;
  Array<Mat3> inverse_inertia;
  Array<std::uint8_t> locks;

  void upload(const CcpBodies& bodies) {
    exec::copy_to_array(predicted_linear, bodies.velocity);
    exec::copy_to_array(predicted_angular, bodies.angular_velocity);
    exec::copy_to_array(inverse_mass, bodies.inverse_mass);
    exec::copy_to_array(inverse_inertia_scalar, bodies.inverse_inertia_scalar);
    exec::copy_to_array(inverse_inertia, bodies.inverse_inertia);
    exec::copy_to_array(locks, bodies.locks);
    linear.resize(bodies.size());
    angular.resize(bodies.size());
  }
  std::size_t bytes() const {
    return exec::bytes_of(predicted_linear) + exec::bytes_of(predicted_angular) +
           exec::bytes_of(linear) + exec::bytes_of(angular) + exec::bytes_of(inverse_mass) +
           exec::bytes_of(inverse_inertia_scalar) + exec::bytes_of(inverse_inertia) +
           exec::bytes_of(locks);
  }
  CcpBodiesView view() const {
    return {inverse_mass.data(), inverse_inertia.data(), inverse_inertia.size(),
            inverse_inertia_scalar.data(), locks.data()};
  }
};

// A group's copy on the device: ConstraintGroup's passes over device arrays (gamma and out
// point at the group's own unknowns).
template <class Backend>
class DeviceCcpGroup {
 public:
  virtual ~DeviceCcpGroup() = default;
  virtual void apply_impulses(const Real* gamma, DeviceCcpBodies<Backend>& bodies) = 0;
  // The rows' velocities less their targets, plus E gamma for compliant rows.
  virtual void row_velocities(const Real* gamma, const DeviceCcpBodies<Backend>& bodies,
                              Real* out) = 0;
  virtual void project(Real* gamma) = 0;
  virtual void diagonal(const DeviceCcpBodies<Backend>& bodies, Real* out) = 0;
  virtual std::size_t bytes() const = 0;  // of the device's memory it holds
};

template <class Backend>
class DeviceCcpProblem {
 public:
  using Vector = typename Backend::template Array<Real>;
  // A group's device copy, or nullptr for a kind this maker does not know.
  using GroupCopier =
      std::function<std::unique_ptr<DeviceCcpGroup<Backend>>(const ConstraintGroup&)>;

  // Adds a copier: each group of a problem is copied by the first copier that knows its kind
  // (add_ccp_group_copiers in device_ccp_groups.hpp adds those of row groups and sphere contacts).
  void add_copier(GroupCopier copier) { copiers_.push_back(std::move(copier)); }

  // Copies `problem` (its bodies, its groups and their warm start) to the device; `problem`
  // receives the impulses when the solve stores them.
  void upload(CcpProblem& problem) {
    problem_ = &problem;
    bodies_.upload(problem.bodies);
    groups_.clear();
    for (const ConstraintGroup* group : problem.groups()) groups_.push_back(copy_of(*group));
    offsets_ = problem.offsets();
  }

  // The solvers' space (ccp_iterations.hpp).
  std::size_t size() const { return problem_->size(); }
  static void copy(Vector& to, const Vector& from) { to.copy_from(from); }
  void gradient(const Vector& x, Vector& g) {
    bodies_.linear.copy_from(bodies_.predicted_linear);
    bodies_.angular.copy_from(bodies_.predicted_angular);
    for (std::size_t k = 0; k < groups_.size(); ++k)
      groups_[k]->apply_impulses(x.data() + offsets_[k], bodies_);
    for (std::size_t k = 0; k < groups_.size(); ++k)
      groups_[k]->row_velocities(x.data() + offsets_[k], bodies_, g.data() + offsets_[k]);
  }
  void project(Vector& x) {
    for (std::size_t k = 0; k < groups_.size(); ++k) groups_[k]->project(x.data() + offsets_[k]);
  }
  void diagonal(Vector& d) {
    for (std::size_t k = 0; k < groups_.size(); ++k)
      groups_[k]->diagonal(bodies_, d.data() + offsets_[k]);
  }
  void warm_start(Vector& x) {
    host_.resize(size());
    problem_->warm_start(host_);
    x.from_host(host_.data(), host_.size());
  }
  void store(const Vector& x) {
    exec::copy_from_array(host_, x);
    problem_->store(host_);
  }
  template <class Body>
  static void for_each(std::size_t n, const Body& body) {
    Backend::for_each(n, body);
  }
  template <class Value>
  double sum_of(std::size_t n, const Value& value) {
    return Backend::block_sum_of(n, value, workspace_);
  }
  template <class Value>
  double max_of(std::size_t n, const Value& value) {
    return Backend::max_of(n, value, workspace_);
  }

  // The device's memory the last solve took [bytes]: the bodies, the groups and the solver's
  // vectors (APGD's eleven, the most of the two solvers).
  std::size_t bytes() const {
    std::size_t total = bodies_.bytes() + 11 * sizeof(Real) * size();
    for (const auto& group : groups_) total += group->bytes();
    return total;
  }

  // The bodies' velocities after the last gradient's impulses (the solution's, after a solve).
  void download_velocities(BodyVelocities& u) const {
    exec::copy_from_array(u.linear, bodies_.linear);
    exec::copy_from_array(u.angular, bodies_.angular);
  }

 private:
  std::unique_ptr<DeviceCcpGroup<Backend>> copy_of(const ConstraintGroup& group) const {
    for (const GroupCopier& copier : copiers_) {
      if (auto copy = copier(group)) return copy;
    }
    throw std::logic_error("DeviceCcpProblem: a group with no device copy");
  }

  CcpProblem* problem_ = nullptr;
  DeviceCcpBodies<Backend> bodies_;
  std::vector<std::unique_ptr<DeviceCcpGroup<Backend>>> groups_;
  std::vector<std::size_t> offsets_;
  std::vector<GroupCopier> copiers_;
  std::vector<Real> host_;  // the warm start and the solution on their way
  typename Backend::Workspace workspace_;
};

// Adds to `device` a copier of the groups of kind Host, copied as Device (constructed from the
// host's group).
template <class Host, class Device, class Backend>
void add_copier_of(DeviceCcpProblem<Backend>& device) {
  device.add_copier([](const ConstraintGroup& group) -> std::unique_ptr<DeviceCcpGroup<Backend>> {
    if (const auto* host = dynamic_cast<const Host*>(&group))
      return std::make_unique<Device>(*host);
    return nullptr;
  });
}

// solve_ccp on the device: `problem` copied there, solved by settings.solver, its groups given
// the impulses and `velocities` the bodies' velocities after them.
template <class Backend>
CcpResult solve_ccp_on(DeviceCcpProblem<Backend>& device, CcpProblem& problem,
                       const CcpSettings& settings, BodyVelocities& velocities) {
  device.upload(problem);
  CcpResult result;
  if (settings.solver == "apgd") {
    result = ccp_iterations::apgd(device, settings);
  } else if (settings.solver == "jacobi") {
    result = ccp_iterations::projected_jacobi(device, settings);
  } else {
    throw std::invalid_argument("unknown complementarity solver '" + settings.solver + "'");
  }
  device.download_velocities(velocities);
  return result;
}

}  // namespace sluice
