#include "sluice/particles/particle_set.hpp"

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
