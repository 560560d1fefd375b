#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#include "sluice/exec/cuda_backend.cuh"
#include "sluice/exec/cuda_backend_check.hpp"

namespace sluice::exec {

namespace {
struct Twice {
  std::uint32_t* out;
  __host__ __device__ void operator()(std::size_t i) const {
    out[i] = 2 * static_cast<std::uint32_t>(i);
  }
};
struct Hump {  // largest at i = n / 3
  std::size_t n;
  __host__ __device__ double operator()(std::size_t i) const {
    const double x = static_cast<double>(i) - static_cast<double>(n / 3);
    return -x * x;
  }
};
// A fixed pseudo-random key with many repeats: the sort must keep equal keys in index order.
std::uint32_t key_of(std::size_t i) {
  return static_cast<std::uint32_t>((i * 2654435761u) % 97u);
}
}  // namespace

std::string check_cuda_backend(std::size_t n) {
  std::string report;
  auto expect = [&](bool ok, const char* what) {
    if (!ok) report += std::string(what) + " disagrees with the host\n";
  };
  using Array = CudaBackend::Array<std::uint32_t>;

  std::vector<std::uint32_t> host(n), back(n);
  Array a;
  a.resize(n);
  CudaBackend::for_each(n, Twice{a.data()});
  a.to_host(back.data(), n);
  for (std::size_t i = 0; i < n; ++i) host[i] = 2 * static_cast<std::uint32_t>(i);
  expect(back == host, "for_each");

  CudaBackend::Workspace workspace;
  Array keys, values;
  keys.resize(n);
  values.resize(n);
  std::vector<std::uint32_t> k(n), v(n);
  for (std::size_t i = 0; i < n; ++i) {
    k[i] = key_of(i);
    v[i] = static_cast<std::uint32_t>(i);
  }
  keys.from_host(k.data(), n);
  values.from_host(v.data(), n);
  CudaBackend::sort_by_key(keys, values, n, 7, workspace);
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t x, std::uint32_t y) { return k[x] < k[y]; });
  values.to_host(back.data(), n);
  expect(back == order, "sort_by_key (stable)");

  std::vector<std::uint32_t> ones(n, 1), sums(n);
  Array in, out;
  in.resize(n);
  out.resize(n);
  in.from_host(ones.data(), n);
  CudaBackend::inclusive_scan(in.data(), out.data(), n, workspace);
  out.to_host(sums.data(), n);
  std::vector<std::uint32_t> expected(n);
  std::iota(expected.begin(), expected.end(), 1u);
  expect(sums == expected, "inclusive_scan");

  expect(CudaBackend::max_of(n, Hump{n}, workspace) == 0.0, "max_of");
  return report;
}

}  // namespace sluice::exec
