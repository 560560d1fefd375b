// The device run of wcsph_device_run.hpp: the particle base's services on the device
// (particle_device_run.hpp, which describes what a backend offers) and wcsph's own stages, the
// loop bodies the host runs (wcsph_loop_bodies.hpp, adami_walls.hpp) over the device's arrays.
// Included by wcsph_device_run.cpp (the host's threads, the emulated device) and
// wcsph_device_cuda.cu (CUDA), so everything here compiles under both.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "sluice/fluid/particle_device_run.hpp"
#include "sluice/fluid/wcsph/adami_walls.hpp"
#include "sluice/fluid/wcsph/wcsph_device_run.hpp"
#include "sluice/fluid/wcsph/wcsph_loop_bodies.hpp"

namespace sluice {

// Device bytes a particle takes in a run over a set of `layout`'s fields: the particle base's
// (particle_device_run.hpp) and the packed copy, 15 floats, and 8 more for each fluid particle
// (the fluid's own arrays), counted for every particle of an empty layout (the size estimate's
// bound). The count of fluid before each particle is the base's.
template <int D, class Backend>
double wcsph_device_run_bytes_per_particle(const ParticleSet<D>& layout) {
  std::size_t fluid = 0;
  for (std::size_t i = 0; i < layout.size(); ++i) fluid += layout.is_fluid(i) ? 1 : 0;
  const double fluid_share =
      layout.size() > 0 ? static_cast<double>(fluid) / static_cast<double>(layout.size()) : 1.0;
  return ParticleDeviceRun<D, Backend>::bytes_per_particle(layout) + 15 * 4 + 8 * 4 * fluid_share;
}

template <int D, class Kernel, class Backend>
class WcsphDeviceRunOn final : public ParticleDeviceServices<D, Backend, WcsphDeviceRun<D>> {
  template <class T>
  using Array = typename Backend::template Array<T>;
  using typename WcsphDeviceRun<D>::Extremes;
  using ParticleDeviceServices<D, Backend, WcsphDeviceRun<D>>::base_;

 public:
  explicit WcsphDeviceRunOn(const WcsphDeviceSetup<D, Kernel>& setup)
      : ParticleDeviceServices<D, Backend, WcsphDeviceRun<D>>(setup.base),
        constants_(setup.constants) {}

  double bytes_per_particle() const override { return bytes_per_particle_; }

  void upload(const ParticleSet<D>& host, const std::vector<Vec3>& point_acceleration,
              const std::vector<std::uint32_t>& cell_start) override {
    const std::size_t n = host.size();
    for (auto& a : packed_position_) a.resize(n);
    for (auto& a : packed_velocity_) a.resize(n);
    for (auto& a : packed_viscous_velocity_) a.resize(n);
    for (auto* a : {&packed_density_, &packed_pressure_, &packed_pressure_term_, &packed_volume_,
                    &packed_fluid_, &packed_viscous_weight_})
      a->resize(n);
    base_.upload(host, point_acceleration, cell_start);
    const std::size_t fluid = base_.fluid_count();
    for (auto& a : fluid_position_) a.resize(fluid);
    for (auto& a : fluid_velocity_) a.resize(fluid);
    fluid_density_.resize(fluid);
    fluid_pressure_.resize(fluid);
    find_fields();
    bytes_per_particle_ = wcsph_device_run_bytes_per_particle<D, Backend>(host);
    // The packed copy the host's last rates read, for the bodies' first loads.
    pack(true);
  }

  void kick_drift(Real dt) override {
    base_.for_each(WcsphKickDrift<D>{fields(), dt, constants_.eos});
  }

  void sort_by_cell() override {
    base_.sort_by_cell();
    find_fields();  // the sort's gather swapped every field's array
  }

  void update_walls() override {
    pack(false);
    base_.for_each_boundary(AdamiWall<D, Kernel>{neighbourhood()});
  }

  void compute_rates() override {
    pack(true);
    base_.for_each_fluid(WcsphRates<D, Kernel>{neighbourhood()});
  }

  void kick(Real dt) override { base_.for_each(WcsphKick<D>{fields(), dt, constants_.eos}); }

  Extremes extremes() const override {
    const WcsphFields<D> f = fields();
    Extremes e;
    e.max_speed = base_.max_of(FluidMagnitude<D>{f, f.velocity});
    e.max_acceleration = base_.max_of(FluidMagnitude<D>{f, f.acceleration});
    return e;
  }

  void body_loads(const std::vector<Vec3>& centre, std::vector<Wrench>& out) const override {
    base_.body_loads(centre, out, [&](Real* point_force) {
      return WcsphBodyPointForce<D, Kernel>{neighbourhood(), point_force};
    });
  }

 private:
  // The fields' arrays, found by name once after each upload and sort (the only times they
  // move), not in every stage: a GPU step is short enough for the look-ups to show.
  void find_fields() { fields_ = wcsph_fields<D>(base_.particles(), base_.point_acceleration()); }
  const WcsphFields<D>& fields() const { return fields_; }
  template <class T>
  static T* mutable_data(const Array<T>& a) {
    return const_cast<T*>(a.data());
  }

  WcsphNeighbourhood<D, Kernel> neighbourhood() const {
    return {fields(), packed_view(), base_.cells(), constants_};
  }

  PackedParticles::Arrays packed_arrays() const {
    PackedParticles::Arrays p{};
    for (int a = 0; a < 3; ++a) {
      p.position[a] = mutable_data(packed_position_[a]);
      p.velocity[a] = mutable_data(packed_velocity_[a]);
      p.viscous_velocity[a] = mutable_data(packed_viscous_velocity_[a]);
    }
    p.density = mutable_data(packed_density_);
    p.pressure = mutable_data(packed_pressure_);
    p.pressure_term = mutable_data(packed_pressure_term_);
    p.volume = mutable_data(packed_volume_);
    p.fluid = mutable_data(packed_fluid_);
    p.viscous_weight = mutable_data(packed_viscous_weight_);
    p.fluid_before = base_.fluid_before();
    for (int a = 0; a < 3; ++a) {
      p.fluid_position[a] = mutable_data(fluid_position_[a]);
      p.fluid_velocity[a] = mutable_data(fluid_velocity_[a]);
    }
    p.fluid_density = mutable_data(fluid_density_);
    p.fluid_pressure = mutable_data(fluid_pressure_);
    return p;
  }
  PackedParticles::View packed_view() const { return packed_arrays().view(); }

  void pack(bool with_rates) {
    base_.for_each(WcsphPack<D>{fields(), packed_arrays(), constants_.no_slip, with_rates});
  }

  WcsphConstants<D, Kernel> constants_;
  WcsphFields<D> fields_;
  double bytes_per_particle_ = 0;
  Array<float> packed_position_[3], packed_velocity_[3], packed_viscous_velocity_[3];
  Array<float> packed_density_, packed_pressure_, packed_pressure_term_, packed_volume_,
      packed_fluid_, packed_viscous_weight_;
  Array<float> fluid_position_[3], fluid_velocity_[3], fluid_density_, fluid_pressure_;
};

}  // namespace sluice
