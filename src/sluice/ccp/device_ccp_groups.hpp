// The device copies (device_ccp_problem.hpp) of the groups this module defines: row groups
// (joints, the rigid bodies' contacts, a fluid's rows on the bodies; row_group_rows.hpp) and a
// granular fluid's sphere contacts (sphere_contact_rows.hpp).
#pragma once

#include "sluice/ccp/device_ccp_problem.hpp"
#include "sluice/ccp/row_group.hpp"
#include "sluice/ccp/sphere_contacts.hpp"

namespace sluice {

template <class Backend>
class DeviceRowGroup final : public DeviceCcpGroup<Backend> {
 public:
  explicit DeviceRowGroup(const RowGroup& group) {
    exec::copy_to_array(rows_, group.rows());
    exec::copy_to_array(blocks_, group.blocks());
  }
  void apply_impulses(const Real* gamma, DeviceCcpBodies<Backend>& b) override {
    if (rows_.size() == 0) return;
    Backend::for_each(1, RowImpulses{rows_.data(), rows_.size(), b.view(), gamma, b.linear.data(),
                                     b.angular.data()});
  }
  void row_velocities(const Real*, const DeviceCcpBodies<Backend>& b, Real* out) override {
    Backend::for_each(rows_.size(),
                      RowVelocity{rows_.data(), b.linear.data(), b.angular.data(), out});
  }
  void project(Real* gamma) override {
    Backend::for_each(blocks_.size(), RowProjection{rows_.data(), blocks_.data(), gamma});
  }
  void diagonal(const DeviceCcpBodies<Backend>& b, Real* out) override {
    Backend::for_each(blocks_.size(), RowDiagonal{rows_.data(), blocks_.data(), b.view(), out});
  }
  std::size_t bytes() const override { return exec::bytes_of(rows_) + exec::bytes_of(blocks_); }

 private:
  typename Backend::template Array<ConstraintRow> rows_;
  typename Backend::template Array<RowBlock> blocks_;
};

template <class Backend>
class DeviceSphereContacts final : public DeviceCcpGroup<Backend> {
 public:
  explicit DeviceSphereContacts(const SphereContacts& group)
      : k_(group.rows_per_contact()),
        first_(group.first()),
        count_(group.count()),
        friction_(group.friction()),
        cohesion_(group.cohesion()),
        rolling_friction_(group.rolling_friction()) {
    const SphereRows rows = group.rows();
    exec::copy_to_array(contacts_, group.contacts());
    exec::copy_to_array(tangents_, rows.tangents, group.tangent_count());
    exec::copy_to_array(list_offsets_, group.list_offsets());
    exec::copy_to_array(list_, group.list());
  }
  void apply_impulses(const Real* gamma, DeviceCcpBodies<Backend>& b) override {
    if (k_ == 1) {
      Backend::for_each(count_, SphereNormalImpulses{list_offsets_.data(), list_.data(), gamma,
                                                     first_, b.view(), b.linear.data()});
      return;
    }
    Backend::for_each(count_, SphereImpulses{rows(), list_offsets_.data(), list_.data(), gamma,
                                             first_, b.view(), b.linear.data(), b.angular.data()});
  }
  void row_velocities(const Real*, const DeviceCcpBodies<Backend>& b, Real* out) override {
    Backend::for_each(contacts_.size(),
                      SphereRowVelocities{rows(), b.linear.data(), b.angular.data(), out});
  }
  void project(Real* gamma) override {
    Backend::for_each(contacts_.size(),
                      SphereProjection{rows(), friction_, cohesion_, rolling_friction_, gamma});
  }
  void diagonal(const DeviceCcpBodies<Backend>& b, Real* out) override {
    Backend::for_each(contacts_.size(), SphereDiagonal{rows(), b.view(), out});
  }
  std::size_t bytes() const override {
    return exec::bytes_of(contacts_) + exec::bytes_of(tangents_) + exec::bytes_of(list_offsets_) +
           exec::bytes_of(list_);
  }

 private:
  SphereRows rows() const { return {contacts_.data(), tangents_.data(), k_}; }

  std::size_t k_, first_, count_;
  Real friction_, cohesion_, rolling_friction_;
  typename Backend::template Array<SphereContact> contacts_;
  typename Backend::template Array<Vec3> tangents_;
  typename Backend::template Array<std::uint32_t> list_offsets_;
  typename Backend::template Array<SphereContactEntry> list_;
};

// Adds the copiers of row groups and sphere contacts to `device`.
template <class Backend>
void add_ccp_group_copiers(DeviceCcpProblem<Backend>& device) {
  add_copier_of<RowGroup, DeviceRowGroup<Backend>>(device);
  add_copier_of<SphereContacts, DeviceSphereContacts<Backend>>(device);
}

}  // namespace sluice
