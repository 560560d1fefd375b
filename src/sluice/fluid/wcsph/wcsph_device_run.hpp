// A WCSPH run whose particles live in a device's memory for the whole run (issue 16): the
// particle base's device (particle_device.hpp, which the base owns and runs its own services
// on) with wcsph's stages, which the model calls each step. The stages run the loop bodies the
// host runs (wcsph_loop_bodies.hpp, adami_walls.hpp) through a backend: CUDA on a GPU
// (wcsph_device_cuda.cu, built where nvcc is found), or the host's own threads over the same
// arrays ("emulated"), which is how the device run's bookkeeping (sort, scans, gathers,
// reductions, transfers) is tested on machines without a GPU.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sluice/core/types.hpp"
#include "sluice/coupling/body_motion.hpp"
#include "sluice/fluid/fluid_energy.hpp"
#include "sluice/fluid/particle_device.hpp"
#include "sluice/fluid/particle_device_run.hpp"
#include "sluice/fluid/wall_surfaces.hpp"
#include "sluice/fluid/wcsph/wcsph_fields.hpp"
#include "sluice/neighbor/cell_list.hpp"

namespace sluice {

enum class WcsphDevice { kCpu, kGpu, kEmulated };

// Whether this build can run `device` here; when not, `why` says what is missing (a build
// without CUDA, no GPU found).
bool wcsph_device_available(WcsphDevice device, std::string& why);

// Bytes of device memory a particle takes in a run of `dimension` (2 or 3): its fields, the
// last good state of those a frame shows, the gather's and the sort's scratch, the lists by
// kind, the packed copy.
double wcsph_device_bytes_per_particle(int dimension);

// The particle base's device (particle_device.hpp: transfers, neighbour stage, body points,
// check, last good state, energy) with wcsph's stages on it.
template <int D>
class WcsphDeviceRun : public ParticleDevice<D> {
 public:
  struct Extremes {
    Real max_speed = 0, max_acceleration = 0;  // over the fluid particles
  };

  // The stages of a step, in the model's order (the base's neighbour stage between the first
  // and the others).
  virtual void kick_drift(Real dt) = 0;
  virtual void update_walls() = 0;
  virtual void compute_rates() = 0;
  virtual void kick(Real dt) = 0;
  virtual Extremes extremes() const = 0;
  // The fluid's force on each body and its moment about the body's `centre` (one per body),
  // from the last rates: summed over the body's points on the device (point_wrench.hpp, the
  // host's arithmetic), so that one transfer of 6 reals per body comes back.
  virtual void body_loads(const std::vector<Vec3>& centre, std::vector<Wrench>& out) const = 0;
};

// What a device run needs besides the particles: the loop bodies' constants and what the
// particle base's services need (particle_device_run.hpp).
template <int D, class Kernel>
struct WcsphDeviceSetup {
  WcsphConstants<D, Kernel> constants;
  ParticleDeviceSetup<D> base;
};

// The run on `device` (kGpu or kEmulated). Throws std::runtime_error when it cannot start.
template <int D, class Kernel>
std::unique_ptr<WcsphDeviceRun<D>> make_wcsph_device_run(WcsphDevice device,
                                                         const WcsphDeviceSetup<D, Kernel>& setup);

}  // namespace sluice
