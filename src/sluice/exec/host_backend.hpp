// The host as a device backend (wcsph_device_run_impl.hpp describes what a backend offers):
// arrays in host memory, loops on the OpenMP policy, a stable sort and a scan. A device run on
// it does every step the way a GPU run does, with its own copy of the particles, its own sort
// and transfers, so tests on machines without a GPU check the device run's bookkeeping.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "sluice/exec/policy.hpp"

namespace sluice::exec {

struct HostBackend {
  static std::string name() { return "emulated (host threads)"; }
  static void finish() {}  // every loop and copy is done when its call returns

  template <class T>
  class Array {
   public:
    T* data() { return values_.data(); }
    const T* data() const { return values_.data(); }
    std::size_t size() const { return values_.size(); }
    void resize(std::size_t n) { values_.resize(n); }
    void swap(Array& other) { values_.swap(other.values_); }
    void from_host(const T* p, std::size_t n, std::size_t offset = 0) {
      std::copy(p, p + n, values_.begin() + static_cast<std::ptrdiff_t>(offset));
    }
    void to_host(T* p, std::size_t n, std::size_t offset = 0) const {
      std::copy_n(values_.begin() + static_cast<std::ptrdiff_t>(offset), n, p);
    }
    void copy_from(const Array& other) { values_ = other.values_; }

   private:
    std::vector<T> values_;
  };

  // What a device keeps between its sorts, scans and reductions: the host needs nothing.
  struct Workspace {};

  // On the calling thread below exec::kParallelFrom indices, where starting the threads costs
  // more than the work (the complementarity solvers' dozen short loops an iteration).
  template <class Body>
  static void for_each(std::size_t n, const Body& body) {
    Default::for_each_light(n, body);
  }

  template <class Value>
  static double max_of(std::size_t n, const Value& value, Workspace&) {
    return Default::max_of(n, value);
  }

  // In index order, as the host's own loops sum.
  template <class Value>
  static double sum_of(std::size_t n, const Value& value, Workspace&) {
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) sum += value(i);
    return sum;
  }

  // In exec::kSumBlock blocks, as the host's policy sums (exec/policy.hpp): the complementarity
  // solvers' sums, which the host's solve takes that way.
  template <class Value>
  static double block_sum_of(std::size_t n, const Value& value, Workspace&) {
    return Default::sum_of(n, value);
  }

  // Stable: particles keep their order within a cell, as the host's counting sort keeps it.
  static void sort_by_key(Array<std::uint32_t>& keys, Array<std::uint32_t>& values, std::size_t n,
                          int /*bits*/, Workspace&) {
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    const std::uint32_t* k = keys.data();
    std::stable_sort(order.begin(), order.end(),
                     [k](std::uint32_t a, std::uint32_t b) { return k[a] < k[b]; });
    std::vector<std::uint32_t> sorted_keys(n), sorted_values(n);
    for (std::size_t i = 0; i < n; ++i) {
      sorted_keys[i] = k[order[i]];
      sorted_values[i] = values.data()[order[i]];
    }
    keys.from_host(sorted_keys.data(), n);
    values.from_host(sorted_values.data(), n);
  }

  static void inclusive_scan(const std::uint32_t* in, std::uint32_t* out, std::size_t n,
                             Workspace&) {
    std::inclusive_scan(in, in + n, out);
  }
};

}  // namespace sluice::exec
