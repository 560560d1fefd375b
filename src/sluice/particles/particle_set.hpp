// Particle storage as a typed structure of arrays: one contiguous array per field. The
// engine's own fields are members; a model adds fields of its own through handles, so hot
// loops never look a field up by name.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sluice/core/types.hpp"

namespace sluice {

// Values of the `kind` array in the output; documented in docs/output.md.
// Body particles are moving walls: the fluid treats them as walls.
enum class ParticleKind : std::int32_t { kFluid = 0, kWall = 1, kBody = 2 };

template <class T>
struct FieldHandle {
  std::size_t index = 0;
};

template <int D>
class ParticleSet {
 public:
  std::vector<Vec<D>> position;
  std::vector<Vec<D>> velocity;
  std::vector<Real> density;
  std::vector<Real> pressure;
  std::vector<Real> mass;
  std::vector<ParticleKind> kind;
  std::vector<std::int32_t> body_point;  // body particles: their index in RigidBodies::points()

  std::size_t size() const { return position.size(); }
  bool is_fluid(std::size_t i) const { return kind[i] == ParticleKind::kFluid; }

  void add(const Vec<D>& x, const Vec<D>& v, Real rho, Real m, ParticleKind k) {
    position.push_back(x);
    velocity.push_back(v);
    density.push_back(rho);
    pressure.push_back(0);
    mass.push_back(m);
    kind.push_back(k);
    body_point.push_back(-1);
    for (auto& f : scalar_fields_) f.push_back(0);
    for (auto& f : vector_fields_) f.push_back(Vec<D>::Zero());
  }

  // A model's own per-particle field, zero-initialised and kept in step with reordering.
  FieldHandle<Real> add_scalar_field() {
    scalar_fields_.emplace_back(size(), Real(0));
    return {scalar_fields_.size() - 1};
  }
  FieldHandle<Vec<D>> add_vector_field() {
    vector_fields_.emplace_back(size(), Vec<D>::Zero());
    return {vector_fields_.size() - 1};
  }
  std::vector<Real>& operator[](FieldHandle<Real> h) { return scalar_fields_[h.index]; }
  const std::vector<Real>& operator[](FieldHandle<Real> h) const { return scalar_fields_[h.index]; }
  std::vector<Vec<D>>& operator[](FieldHandle<Vec<D>> h) { return vector_fields_[h.index]; }
  const std::vector<Vec<D>>& operator[](FieldHandle<Vec<D>> h) const {
    return vector_fields_[h.index];
  }

  // Applies a permutation to every field: after it, particle k is the one that was order[k].
  void reorder(const std::vector<std::uint32_t>& order);

 private:
  std::vector<std::vector<Real>> scalar_fields_;
  std::vector<std::vector<Vec<D>>> vector_fields_;
};

}  // namespace sluice
