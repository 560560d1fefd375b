// Particle storage as a typed structure of arrays: one contiguous array per field. The
// engine's own fields are members; a model adds fields of its own (integer, scalar or vector,
// each with a name and a unit) through handles, so hot loops never look a field up by name.
// Output, the divergence guard and checkpoints see every field through for_each_field.
#pragma once

#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "sluice/core/state_archive.hpp"
#include "sluice/core/types.hpp"
#include "sluice/particles/field_label.hpp"

namespace sluice {

// Values of the `kind` array in the output; documented in docs/output.md. Walls and bodies
// are boundaries the fluid sees; a dummy particle fills out a wall's support without taking
// part in the model's equations (MPS's outer wall layers).
enum class ParticleKind : std::int32_t { kFluid = 0, kWall = 1, kBody = 2, kDummy = 3 };

template <class T>
struct FieldHandle {
  std::size_t index = 0;
};

// How a field's values lie in memory as plain components: `type` and `width` of them a
// particle (a vector's D reals; a kind's 32-bit integer).
template <class Element>
struct FieldComponents {
  using type = Element;
  static constexpr int width = 1;
};
template <class Scalar, int Rows, int Options, int MaxRows, int MaxCols>
struct FieldComponents<Eigen::Matrix<Scalar, Rows, 1, Options, MaxRows, MaxCols>> {
  using type = Scalar;
  static constexpr int width = Rows;
};
template <>
struct FieldComponents<ParticleKind> {
  using type = std::int32_t;
  static constexpr int width = 1;
};

template <int D>
class ParticleSet {
 public:
  static constexpr int kDimension = D;
  std::vector<Vec<D>> position;
  std::vector<Vec<D>> velocity;
  std::vector<Real> density;
  std::vector<Real> pressure;
  std::vector<Real> mass;
  std::vector<ParticleKind> kind;
  std::vector<std::int32_t> body_point;  // body particles: their index among the body points

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
    for (auto& f : int_fields_) f.values.push_back(0);
    for (auto& f : scalar_fields_) f.values.push_back(0);
    for (auto& f : vector_fields_) f.values.push_back(Vec<D>::Zero());
  }

  // A model's own per-particle field, zero-initialised and kept in step with reordering.
  FieldHandle<std::int32_t> add_int_field(FieldLabel label) { return add(int_fields_, label); }
  FieldHandle<Real> add_scalar_field(FieldLabel label) { return add(scalar_fields_, label); }
  FieldHandle<Vec<D>> add_vector_field(FieldLabel label) { return add(vector_fields_, label); }

  template <class T>
  std::vector<T>& operator[](FieldHandle<T> h) {
    return fields<T>()[h.index].values;
  }
  template <class T>
  const std::vector<T>& operator[](FieldHandle<T> h) const {
    return const_cast<ParticleSet&>(*this).fields<T>()[h.index].values;
  }

  template <class T>
  const FieldLabel& label(FieldHandle<T> h) const {
    return const_cast<ParticleSet&>(*this).fields<T>()[h.index].label;
  }

  // visit(label, values) for every field, the engine's first, in a fixed order; `values` is a
  // std::vector of ParticleKind, std::int32_t, Real or Vec<D>.
  template <class Visit>
  void for_each_field(Visit&& visit) const {
    visit_fields(*this, visit);
  }
  template <class Visit>
  void for_each_field(Visit&& visit) {
    visit_fields(*this, visit);
  }

  // The components of the field called `name` as one array: D reals a particle for a vector
  // field, one real or one 32-bit integer (the kinds too) for the others. T is Real or
  // std::int32_t; a field of another type, or none of that name, is a logic error.
  template <class T>
  T* components(const std::string& name);
  template <class T>
  const T* components(const std::string& name) const {
    return const_cast<ParticleSet&>(*this).template components<T>(name);
  }

  // Bytes a particle takes over all fields.
  std::size_t bytes_per_particle() const;

  // Every field of the particles `which`, one after another, appended to `buffer`; and the
  // particles so packed (`count` of them, by a set of the same fields) appended to this set.
  // What halo exchanges and migrations send.
  void pack(const std::vector<std::uint32_t>& which, std::vector<unsigned char>& buffer) const;
  void unpack_append(const unsigned char* buffer, std::size_t count);

  // Makes this set hold the fields of `from`: the values of those for which keep(label) holds,
  // the others empty, with their memory given back (the guard's last good state keeps only
  // what a frame shows).
  template <class Keep>
  void assign_fields(const ParticleSet& from, Keep&& keep) {
    take_labels(int_fields_, from.int_fields_);
    take_labels(scalar_fields_, from.scalar_fields_);
    take_labels(vector_fields_, from.vector_fields_);
    std::vector<const void*> sources;
    visit_fields(from, [&](const FieldLabel&, const auto& values) { sources.push_back(&values); });
    std::size_t k = 0;
    visit_fields(*this, [&](const FieldLabel& label, auto& values) {
      const auto& source = *static_cast<const std::decay_t<decltype(values)>*>(sources.at(k++));
      if (keep(label)) {
        values = source;
      } else {
        values = std::decay_t<decltype(values)>();
      }
    });
  }

  // Applies a permutation to every field: after it, particle k is the one that was order[k]
  // (an `order` shorter than the set drops those it does not name).
  void reorder(const std::vector<std::uint32_t>& order);
  // Keeps the particles `which` alone, in that order (a rank's own after a migration); a field
  // that assign_fields left empty stays empty.
  void keep(const std::vector<std::uint32_t>& which);

  // Checkpoints: every field, each under its name.
  void archive_state(StateArchive& a) {
    visit_fields(*this, [&](const FieldLabel& label, auto& values) {
      a.section(label.name);
      a(values);
    });
  }

 private:
  template <class Self, class Visit>
  static void visit_fields(Self& self, Visit&& visit) {
    visit(FieldLabel{"position", "m", false}, self.position);
    visit(FieldLabel{"velocity", "m/s", true}, self.velocity);
    visit(FieldLabel{"pressure", "Pa", true}, self.pressure);
    visit(FieldLabel{"density", "kg/m^3", true}, self.density);
    visit(FieldLabel{"mass", "kg", false}, self.mass);
    visit(FieldLabel{"kind", "1", true}, self.kind);
    visit(FieldLabel{"body_point", "1", false}, self.body_point);
    for (auto& f : self.int_fields_) visit(f.label, f.values);
    for (auto& f : self.scalar_fields_) visit(f.label, f.values);
    for (auto& f : self.vector_fields_) visit(f.label, f.values);
  }

  template <class T>
  struct Field {
    FieldLabel label;
    std::vector<T> values;
  };

  template <class T>
  static void take_labels(std::vector<Field<T>>& to, const std::vector<Field<T>>& from) {
    to.resize(from.size());
    for (std::size_t k = 0; k < from.size(); ++k) to[k].label = from[k].label;
  }

  template <class T>
  FieldHandle<T> add(std::vector<Field<T>>& fields, FieldLabel label) {
    T zero;
    if constexpr (std::is_arithmetic_v<T>) {
      zero = 0;
    } else {
      zero = T::Zero();
    }
    fields.push_back({std::move(label), std::vector<T>(size(), zero)});
    return {fields.size() - 1};
  }
  template <class T>
  std::vector<Field<T>>& fields() {
    if constexpr (std::is_same_v<T, std::int32_t>) {
      return int_fields_;
    } else if constexpr (std::is_same_v<T, Real>) {
      return scalar_fields_;
    } else {
      return vector_fields_;
    }
  }

  std::vector<Field<std::int32_t>> int_fields_;
  std::vector<Field<Real>> scalar_fields_;
  std::vector<Field<Vec<D>>> vector_fields_;
};

}  // namespace sluice
