// The CUDA execution policy as a device backend (wcsph_device_run_impl.hpp describes what a
// backend offers): arrays in device memory, a loop body run by one thread per index, and the
// sort, scan and reduction of CUB (which ships with the CUDA toolkit). Compiled by nvcc only.
#pragma once

#include <cuda_runtime.h>

#include <cstdint>
#include <cub/cub.cuh>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "sluice/exec/sum_block.hpp"

namespace sluice::exec {

inline void cuda_check(cudaError_t status, const char* what) {
  if (status != cudaSuccess) {
    throw std::runtime_error(std::string("CUDA: ") + what + ": " + cudaGetErrorString(status));
  }
}

template <class Body>
__global__ void run_each(std::size_t n, Body body) {
  const std::size_t i = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
  if (i < n) body(i);
}

template <class Value>
__global__ void evaluate_each(std::size_t n, Value value, double* out) {
  const std::size_t i = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
  if (i < n) out[i] = value(i);
}

// Thread k sums value(i) over block k of kSumBlock indices, in index order.
template <class Value>
__global__ void sum_each_block(std::size_t n, std::size_t blocks, Value value, double* out) {
  const std::size_t k = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
  if (k >= blocks) return;
  const std::size_t begin = k * kSumBlock;
  const std::size_t end = begin + kSumBlock < n ? begin + kSumBlock : n;
  double sum = 0;
  for (std::size_t i = begin; i < end; ++i) sum += value(i);
  out[k] = sum;
}

struct CudaBackend {
  static constexpr int kBlock = 256;

  static std::string name() {
    int device = 0;
    cuda_check(cudaGetDevice(&device), "cudaGetDevice");
    cudaDeviceProp properties{};
    cuda_check(cudaGetDeviceProperties(&properties, device), "cudaGetDeviceProperties");
    return std::string(properties.name) + " (CUDA)";
  }

  static void finish() { cuda_check(cudaDeviceSynchronize(), "waiting for the GPU"); }

  // n values of T in device memory; copies to and from the host are synchronous.
  template <class T>
  class Array {
   public:
    Array() = default;
    Array(const Array&) = delete;
    Array& operator=(const Array&) = delete;
    ~Array() { cudaFree(data_); }  // nothing to report from a destructor

    T* data() { return data_; }
    const T* data() const { return data_; }
    std::size_t size() const { return size_; }
    void resize(std::size_t n) {
      if (n == size_) return;
      cudaFree(data_);
      data_ = nullptr;
      size_ = n;
      if (n > 0) cuda_check(cudaMalloc(&data_, n * sizeof(T)), "cudaMalloc");
    }
    void swap(Array& other) {
      std::swap(data_, other.data_);
      std::swap(size_, other.size_);
    }
    void from_host(const T* p, std::size_t n, std::size_t offset = 0) {
      if (n == 0) return;
      cuda_check(cudaMemcpy(data_ + offset, p, n * sizeof(T), cudaMemcpyHostToDevice),
                 "copy to the device");
    }
    void to_host(T* p, std::size_t n, std::size_t offset = 0) const {
      if (n == 0) return;
      cuda_check(cudaMemcpy(p, data_ + offset, n * sizeof(T), cudaMemcpyDeviceToHost),
                 "copy from the device");
    }
    void copy_from(const Array& other) {
      resize(other.size_);
      if (size_ == 0) return;
      cuda_check(cudaMemcpy(data_, other.data_, size_ * sizeof(T), cudaMemcpyDeviceToDevice),
                 "copy on the device");
    }

   private:
    T* data_ = nullptr;
    std::size_t size_ = 0;
  };

  template <class Body>
  static void for_each(std::size_t n, const Body& body) {
    if (n == 0) return;
    run_each<<<blocks(n), kBlock>>>(n, body);
    cuda_check(cudaGetLastError(), "a loop's launch");
  }

  // What the sort, the scan and the reductions keep between calls, owned by the run that calls
  // them and grown as needed (a cudaMalloc per call would cost more than the small steps it
  // serves): the sort's second buffers, the values a reduction reduces (and its result), and
  // CUB's temporary storage.
  class Workspace {
   public:
    void* temporary(std::size_t bytes) {
      if (temporary_.size() < bytes) temporary_.resize(bytes);
      return temporary_.data();
    }
    Array<std::uint32_t> other_keys, other_values;
    Array<double> values;

   private:
    Array<unsigned char> temporary_;
  };

  template <class Value>
  static double max_of(std::size_t n, const Value& value, Workspace& workspace) {
    if (n == 0) return -std::numeric_limits<double>::infinity();
    return reduce(n, value, workspace, "cub::DeviceReduce::Max",
                  [](auto&&... args) { return cub::DeviceReduce::Max(args...); });
  }

  template <class Value>
  static double sum_of(std::size_t n, const Value& value, Workspace& workspace) {
    if (n == 0) return 0;
    return reduce(n, value, workspace, "cub::DeviceReduce::Sum",
                  [](auto&&... args) { return cub::DeviceReduce::Sum(args...); });
  }

  // In kSumBlock blocks, each in index order, and the blocks' sums in block order on the host:
  // the additions the host's policy makes (exec/policy.hpp), for the complementarity solvers.
  template <class Value>
  static double block_sum_of(std::size_t n, const Value& value, Workspace& workspace) {
    const std::size_t blocks = (n + kSumBlock - 1) / kSumBlock;
    if (blocks == 0) return 0;
    Array<double>& values = workspace.values;
    if (values.size() < blocks) values.resize(blocks);
    sum_each_block<<<CudaBackend::blocks(blocks), kBlock>>>(n, blocks, value, values.data());
    cuda_check(cudaGetLastError(), "a block sum's launch");
    std::vector<double> partial(blocks);
    values.to_host(partial.data(), blocks);
    double total = 0;
    for (const double p : partial) total += p;
    return total;
  }

  // Stable, by the keys' lowest `bits` bits (CUB's radix sort keeps equal keys in order).
  static void sort_by_key(Array<std::uint32_t>& keys, Array<std::uint32_t>& values, std::size_t n,
                          int bits, Workspace& workspace) {
    if (n == 0) return;
    workspace.other_keys.resize(keys.size());
    workspace.other_values.resize(values.size());
    cub::DoubleBuffer<std::uint32_t> k(keys.data(), workspace.other_keys.data());
    cub::DoubleBuffer<std::uint32_t> v(values.data(), workspace.other_values.data());
    std::size_t bytes = 0;
    cuda_check(cub::DeviceRadixSort::SortPairs(nullptr, bytes, k, v, static_cast<int>(n), 0, bits),
               "cub::DeviceRadixSort::SortPairs");
    cuda_check(cub::DeviceRadixSort::SortPairs(workspace.temporary(bytes), bytes, k, v,
                                               static_cast<int>(n), 0, bits),
               "cub::DeviceRadixSort::SortPairs");
    if (k.Current() != keys.data()) keys.swap(workspace.other_keys);
    if (v.Current() != values.data()) values.swap(workspace.other_values);
  }

  static void inclusive_scan(const std::uint32_t* in, std::uint32_t* out, std::size_t n,
                             Workspace& workspace) {
    if (n == 0) return;
    std::size_t bytes = 0;
    cuda_check(cub::DeviceScan::InclusiveSum(nullptr, bytes, in, out, static_cast<int>(n)),
               "cub::DeviceScan::InclusiveSum");
    cuda_check(cub::DeviceScan::InclusiveSum(workspace.temporary(bytes), bytes, in, out,
                                             static_cast<int>(n)),
               "cub::DeviceScan::InclusiveSum");
  }

 private:
  static unsigned blocks(std::size_t n) { return static_cast<unsigned>((n + kBlock - 1) / kBlock); }

  // value(i) for i in [0, n) into the workspace's values, reduced there by CUB's `reduction`
  // (called as reduction(temporary, bytes, in, out, n)) into values[n], which comes back.
  template <class Value, class Reduction>
  static double reduce(std::size_t n, const Value& value, Workspace& workspace, const char* what,
                       Reduction&& reduction) {
    Array<double>& values = workspace.values;
    if (values.size() < n + 1) values.resize(n + 1);
    evaluate_each<<<blocks(n), kBlock>>>(n, value, values.data());
    cuda_check(cudaGetLastError(), "a reduction's launch");
    double* in = values.data();
    const int count = static_cast<int>(n);
    std::size_t bytes = 0;
    cuda_check(reduction(nullptr, bytes, in, in + n, count), what);
    cuda_check(reduction(workspace.temporary(bytes), bytes, in, in + n, count), what);
    double result = 0;
    values.to_host(&result, 1, n);
    return result;
  }
};

}  // namespace sluice::exec
