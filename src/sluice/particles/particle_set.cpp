#include "sluice/particles/particle_set.hpp"

#include <algorithm>

#include "sluice/exec/policy.hpp"

namespace sluice {

namespace {
// Gathers `field` through `order`.
template <class T>
void permute(std::vector<T>& field, const std::vector<std::uint32_t>& order) {
  std::vector<T> sorted(field.size());
  exec::Default::for_each(order.size(), [&](std::size_t k) { sorted[k] = field[order[k]]; });
  field.swap(sorted);
}
}  // namespace

template <int D>
void ParticleSet<D>::reorder(const std::vector<std::uint32_t>& order) {
  // A set already in order (a device's copy come back, a tank at rest) skips the copies.
  std::uint32_t k = 0;
  if (std::all_of(order.begin(), order.end(), [&](std::uint32_t i) { return i == k++; })) return;
  permute(position, order);
  permute(velocity, order);
  permute(density, order);
  permute(pressure, order);
  permute(mass, order);
  permute(kind, order);
  permute(body_point, order);
  for (auto& f : int_fields_) permute(f.values, order);
  for (auto& f : scalar_fields_) permute(f.values, order);
  for (auto& f : vector_fields_) permute(f.values, order);
}

template class ParticleSet<2>;
template class ParticleSet<3>;

}  // namespace sluice
