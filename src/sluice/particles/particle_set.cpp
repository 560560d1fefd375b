#include "sluice/particles/particle_set.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <type_traits>

#include "sluice/exec/policy.hpp"

namespace sluice {

namespace {
// Gathers `field` through `order` (those it does not name go). The result keeps room for as
// many as the field held: a split run's sort drops the last step's ghosts, and the next
// exchange appends about as many again without reallocating every field (at 3.5 million
// particles a rank, half the ghosts' time: docs/performance.md). One rank alone drops none,
// and keeps no more.
template <class T>
void permute(std::vector<T>& field, const std::vector<std::uint32_t>& order) {
  std::vector<T> sorted;
  sorted.reserve(std::max(order.size(), field.size()));
  sorted.resize(order.size());
  exec::Default::for_each(order.size(), [&](std::size_t k) { sorted[k] = field[order[k]]; });
  field.swap(sorted);
}
}  // namespace

template <int D>
void ParticleSet<D>::reorder(const std::vector<std::uint32_t>& order) {
  // A set already in order (a device's copy come back, a tank at rest) skips the copies.
  std::uint32_t k = 0;
  if (order.size() == size() &&
      std::all_of(order.begin(), order.end(), [&](std::uint32_t i) { return i == k++; }))
    return;
  keep(order);
}

template <int D>
void ParticleSet<D>::keep(const std::vector<std::uint32_t>& order) {
  // A field that assign_fields left empty stays so.
  visit_fields(*this, [&](const FieldLabel&, auto& values) {
    if (!values.empty()) permute(values, order);
  });
}

template <int D>
template <class T>
T* ParticleSet<D>::components(const std::string& name) {
  T* found = nullptr;
  bool exists = false;
  for_each_field([&](const FieldLabel& label, auto& values) {
    using Components = FieldComponents<typename std::decay_t<decltype(values)>::value_type>;
    if (label.name != name) return;
    exists = true;
    if constexpr (std::is_same_v<typename Components::type, T>) {
      found = reinterpret_cast<T*>(values.data());
    } else {
      throw std::logic_error("particle field " + name + " is not of the type asked for");
    }
  });
  if (!exists) throw std::logic_error("no particle field " + name);
  return found;
}

template <int D>
std::size_t ParticleSet<D>::bytes_per_particle() const {
  std::size_t bytes = 0;
  for_each_field([&](const FieldLabel&, const auto& values) {
    bytes += sizeof(typename std::decay_t<decltype(values)>::value_type);
  });
  return bytes;
}

template <int D>
void ParticleSet<D>::pack(const std::vector<std::uint32_t>& which,
                          std::vector<unsigned char>& buffer) const {
  const std::size_t start = buffer.size();
  buffer.resize(start + which.size() * bytes_per_particle());
  unsigned char* out = buffer.data() + start;
  for_each_field([&](const FieldLabel&, const auto& values) {
    using Element = typename std::decay_t<decltype(values)>::value_type;
    using Components = FieldComponents<Element>;
    const auto* from = reinterpret_cast<const typename Components::type*>(values.data());
    for (const std::uint32_t i : which) {
      std::memcpy(out, from + Components::width * i, sizeof(Element));
      out += sizeof(Element);
    }
  });
}

template <int D>
void ParticleSet<D>::unpack_append(const unsigned char* buffer, std::size_t count) {
  const std::size_t start = size();
  for_each_field([&](const FieldLabel&, auto& values) {
    using Element = typename std::decay_t<decltype(values)>::value_type;
    using Components = FieldComponents<Element>;
    values.resize(start + count);
    auto* to = reinterpret_cast<typename Components::type*>(values.data() + start);
    std::memcpy(to, buffer, count * sizeof(Element));
    buffer += count * sizeof(Element);
  });
}

#define SLUICE_COMPONENTS(D, T) template T* ParticleSet<D>::components<T>(const std::string&);
SLUICE_COMPONENTS(2, Real)
SLUICE_COMPONENTS(3, Real)
SLUICE_COMPONENTS(2, std::int32_t)
SLUICE_COMPONENTS(3, std::int32_t)
#undef SLUICE_COMPONENTS

template class ParticleSet<2>;
template class ParticleSet<3>;

}  // namespace sluice
