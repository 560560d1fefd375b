// Whole copies between a host's values and a backend's array (exec/host_backend.hpp,
// exec/cuda_backend.cuh): the array takes the values' size; and an array's bytes.
#pragma once

#include <cstddef>
#include <vector>

namespace sluice::exec {

template <class Array, class T>
void copy_to_array(Array& to, const T* from, std::size_t n) {
  to.resize(n);
  to.from_host(from, n);
}
template <class Array, class T>
void copy_to_array(Array& to, const std::vector<T>& from) {
  copy_to_array(to, from.data(), from.size());
}

template <class Array, class T>
void copy_from_array(std::vector<T>& to, const Array& from) {
  to.resize(from.size());
  from.to_host(to.data(), to.size());
}

// The memory an array holds [bytes].
template <class Array>
std::size_t bytes_of(const Array& a) {
  return a.size() * sizeof(*a.data());
}

}  // namespace sluice::exec
