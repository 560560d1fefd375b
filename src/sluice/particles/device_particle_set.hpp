// A particle set's copy in a device's memory (a GPU's, or the host's own for the emulated run):
// one array per field of the host's set, with the field's name and unit, made from the host's
// labels when uploaded. So the fields a model adds are moved, sorted, remembered and counted in
// memory with the engine's own, and nowhere is a list of them written out. Over a backend of
// exec/ (host_backend.hpp describes what one offers).
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "sluice/core/host_device.hpp"
#include "sluice/particles/particle_set.hpp"

namespace sluice {

// Device bytes a particle with the fields of `layout` takes in a DeviceParticleSet: its fields,
// those that keep(label) remembers, and the gather's scratch (an array of each width). Known
// before a run starts.
template <int D, class Keep>
double device_bytes_per_particle(const ParticleSet<D>& layout, Keep&& keep) {
  double bytes = 0;
  bool real_width[D + 1] = {}, integer_width = false;
  layout.for_each_field([&](const FieldLabel& label, const auto& values) {
    using Components = FieldComponents<typename std::decay_t<decltype(values)>::value_type>;
    using T = typename Components::type;
    bytes += Components::width * sizeof(T) * (keep(label) ? 2 : 1);
    if constexpr (std::is_same_v<T, Real>) {
      real_width[Components::width] = true;
    } else {
      integer_width = true;
    }
  });
  for (int w = 1; w <= D; ++w) bytes += real_width[w] ? w * sizeof(Real) : 0;
  return bytes + (integer_width ? sizeof(std::int32_t) : 0);
}

// to[k] = from[order[k]], `width` values a particle: a loop body (outside the class, as CUDA
// launches no private type).
template <class T>
struct GatherParticles {
  const T* from;
  T* to;
  const std::uint32_t* order;
  int width;
  SLUICE_HOST_DEVICE void operator()(std::size_t k) const {
    const std::size_t i = order[k];
    for (int a = 0; a < width; ++a) to[width * k + a] = from[width * i + a];
  }
};

template <int D, class Backend>
class DeviceParticleSet {
  template <class T>
  using Array = typename Backend::template Array<T>;

 public:
  std::size_t size() const { return size_; }

  // Makes the device's fields those of `host` (labels and values), in its order.
  void upload(const ParticleSet<D>& host) {
    size_ = host.size();
    reals_.clear();
    integers_.clear();
    host.for_each_field([&](const FieldLabel& label, const auto& values) {
      using Components = FieldComponents<typename std::decay_t<decltype(values)>::value_type>;
      Field<typename Components::type>& field = add<typename Components::type>(label);
      field.width = Components::width;
      field.values.resize(Components::width * size_);
      field.values.from_host(reinterpret_cast<const typename Components::type*>(values.data()),
                             Components::width * size_);
    });
  }

  // Copies every field into `host`, a set of the same fields, resized to the device's count.
  void download(ParticleSet<D>& host) const { copy_to(host, false); }

  // The components of the field called `name` (D reals a particle for a vector field; see
  // ParticleSet::components), in the device's memory.
  template <class T>
  T* components(const std::string& name) const {
    for (auto& field : fields<T>()) {
      if (field->label.name == name) return const_cast<T*>(field->values.data());
    }
    throw std::logic_error("no device particle field " + name + " of the type asked for");
  }

  // Reorders every field: after it, particle k is the one that was order[k] (a device array).
  void gather(const std::uint32_t* order) {
    gather_each(reals_, order);
    gather_each(integers_, order);
  }

  // Keeps the fields for which keep(label) holds as they are now (on the device), for
  // download_remembered, which copies them into the host's set (its other fields untouched).
  template <class Keep>
  void remember(Keep&& keep) {
    remember_each(reals_, keep);
    remember_each(integers_, keep);
  }
  void download_remembered(ParticleSet<D>& host) const { copy_to(host, true); }

 private:
  template <class T>
  struct Field {
    FieldLabel label;
    int width = 1;
    Array<T> values;
    Array<T> good;  // the remembered values
    bool remembered = false;
  };

  template <class T>
  std::vector<std::unique_ptr<Field<T>>>& fields() {
    if constexpr (std::is_same_v<T, Real>) {
      return reals_;
    } else {
      return integers_;
    }
  }
  template <class T>
  const std::vector<std::unique_ptr<Field<T>>>& fields() const {
    return const_cast<DeviceParticleSet*>(this)->fields<T>();
  }
  template <class T>
  Field<T>& add(const FieldLabel& label) {
    fields<T>().push_back(std::make_unique<Field<T>>());
    fields<T>().back()->label = label;
    return *fields<T>().back();
  }

  // Through a scratch array of the field's size, which the field then swaps with (so each
  // scratch, one per width, keeps its size, and a device allocates nothing in a step).
  template <class T>
  void gather_each(std::vector<std::unique_ptr<Field<T>>>& list, const std::uint32_t* order) {
    for (auto& field : list) {
      Array<T>& scratch = scratch_of<T>()[field->width];
      scratch.resize(field->values.size());
      Backend::for_each(
          size_, GatherParticles<T>{field->values.data(), scratch.data(), order, field->width});
      field->values.swap(scratch);
    }
  }
  template <class T>
  Array<T>* scratch_of() {
    if constexpr (std::is_same_v<T, Real>) {
      return real_scratch_;
    } else {
      return integer_scratch_;
    }
  }

  template <class T, class Keep>
  static void remember_each(std::vector<std::unique_ptr<Field<T>>>& list, Keep& keep) {
    for (auto& field : list) {
      field->remembered = keep(field->label);
      if (field->remembered) field->good.copy_from(field->values);
    }
  }

  void copy_to(ParticleSet<D>& host, bool remembered) const {
    std::size_t real = 0, integer = 0;
    host.for_each_field([&](const FieldLabel& label, auto& values) {
      using Components = FieldComponents<typename std::decay_t<decltype(values)>::value_type>;
      using T = typename Components::type;
      const auto& field = *fields<T>().at(std::is_same_v<T, Real> ? real++ : integer++);
      if (field.label.name != label.name) {
        throw std::logic_error("the device's particle fields are not the host's");
      }
      if (remembered && !field.remembered) return;
      values.resize(size_);
      (remembered ? field.good : field.values)
          .to_host(reinterpret_cast<T*>(values.data()), Components::width * size_);
    });
  }

  std::size_t size_ = 0;
  // By type, in the host's order; each behind a pointer, as a device array cannot be copied.
  std::vector<std::unique_ptr<Field<Real>>> reals_;
  std::vector<std::unique_ptr<Field<std::int32_t>>> integers_;
  Array<Real> real_scratch_[D + 1];  // by width
  Array<std::int32_t> integer_scratch_[2];
};

}  // namespace sluice
