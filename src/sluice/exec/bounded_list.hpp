// A list of at most N values in place (no heap), for a loop body's scratch on a device, where a
// thread cannot grow a vector; append() tells when it is full. append() on a std::vector, the
// host's scratch, always succeeds, so that one loop body serves both.
#pragma once

#include <cstddef>
#include <vector>

#include "sluice/core/host_device.hpp"

namespace sluice {

template <class T, int N>
struct BoundedList {
  T items[N];
  int count = 0;

  SLUICE_HOST_DEVICE std::size_t size() const { return static_cast<std::size_t>(count); }
  SLUICE_HOST_DEVICE void clear() { count = 0; }
  SLUICE_HOST_DEVICE T& operator[](std::size_t k) { return items[k]; }
  SLUICE_HOST_DEVICE const T& operator[](std::size_t k) const { return items[k]; }
};

// Appends `value`; false where the list is full (it is then unchanged).
template <class T, int N>
SLUICE_HOST_DEVICE bool append(BoundedList<T, N>& list, const T& value) {
  if (list.count == N) return false;
  list.items[list.count++] = value;
  return true;
}
template <class T>
bool append(std::vector<T>& list, const T& value) {
  list.push_back(value);
  return true;
}

}  // namespace sluice
