// Where a monolithic model's complementarity solve runs (`model.device`): on the host, or on the
// emulated device (exec/host_backend.hpp), the problem copied there each solve and solved by the
// same steps in the same order (ccp/device_ccp_problem.hpp), so with the host's answer to the
// bit. The rows are built on the host either way.
#pragma once

#include <algorithm>
#include <functional>
#include <memory>
#include <string>

#include "sluice/ccp/device_ccp_groups.hpp"
#include "sluice/exec/host_backend.hpp"

namespace sluice {

class MonolithicSolve {
 public:
  using Device = DeviceCcpProblem<exec::HostBackend>;

  // On the emulated device when `emulated`; `add_copiers` adds the model's own kinds of group
  // to those of the ccp module.
  explicit MonolithicSolve(bool emulated, const std::function<void(Device&)>& add_copiers = {}) {
    if (!emulated) return;
    device_ = std::make_unique<Device>();
    add_ccp_group_copiers(*device_);
    if (add_copiers) add_copiers(*device_);
  }

  CcpResult operator()(CcpProblem& problem, const CcpSettings& settings,
                       BodyVelocities& velocities) {
    if (!device_) return solve_ccp(problem, settings, velocities);
    const CcpResult result = solve_ccp_on(*device_, problem, settings, velocities);
    largest_bytes_ = std::max(largest_bytes_, device_->bytes());
    return result;
  }

  // The device's memory the largest solve so far took [bytes] (0 on the host).
  std::size_t largest_bytes() const { return largest_bytes_; }
  bool on_device() const { return device_ != nullptr; }

  // For the model's description: where the solve runs.
  std::string where() const {
    return std::string("the complementarity solve on ") +
           (device_ ? exec::HostBackend::name() : "the host");
  }

 private:
  std::unique_ptr<Device> device_;
  std::size_t largest_bytes_ = 0;
};

}  // namespace sluice
