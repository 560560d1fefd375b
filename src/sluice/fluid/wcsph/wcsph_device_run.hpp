// A WCSPH run whose particles live in a device's memory for the whole run (issue 16): the
// model (wcsph_model.hpp) hands it its fields once, calls its stages each step, and copies the
// fields back only for output, probes and checkpoints. The stages run the loop bodies the host
// runs (wcsph_loop_bodies.hpp, adami_walls.hpp) through a backend: CUDA on a GPU
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

template <int D>
class WcsphDeviceRun {
 public:
  struct Extremes {
    Real max_speed = 0, max_acceleration = 0;  // over the fluid particles
  };

  virtual ~WcsphDeviceRun() = default;
  // What runs it, for the run's header: the GPU's name, or "emulated".
  virtual std::string name() const = 0;
  // Bytes of device memory per particle (its fields, the sort's scratch, the last good state).
  virtual double bytes_per_particle() const = 0;

  // Copies every field of `host` (the engine's and wcsph's, whatever their count: the device's
  // set mirrors the host's labels) and the body points' accelerations to the device, or back.
  // The device's order is the host's after an upload; after a download the host holds the
  // device's order, which is sorted by cell as of the step's neighbour sort.
  virtual void upload(const ParticleSet<D>& host, const std::vector<Vec3>& point_acceleration) = 0;
  virtual void download(ParticleSet<D>& host, std::vector<Vec3>& point_acceleration) const = 0;

  // The stages of a step, in the model's order.
  virtual void kick_drift(Real dt) = 0;
  // Puts back fluid found in a wall's layers (wall_surfaces.hpp), then sorts by cell.
  virtual void sort_by_cell() = 0;
  // The bodies moved: `body_motion` holds each body's kinematics (pack_body_motion); the device
  // places their points (rigid_point.hpp, the host's arithmetic) and their particles.
  virtual void set_body_motion(const std::vector<Real>& body_motion) = 0;
  virtual void update_walls() = 0;
  virtual void compute_rates() = 0;
  virtual void kick(Real dt) = 0;
  virtual Extremes extremes() const = 0;
  // The fluid's kinetic and potential energy and mass (fluid_energy.hpp), summed on the device
  // (energy.csv's rows cost no transfer of the particles). `gravity` holds D reals.
  virtual FluidEnergy energy(const Real* gravity) const = 0;
  // The fluid's force on each body and its moment about the body's `centre` (one per body),
  // from the last rates: summed over the body's points on the device (point_wrench.hpp, the
  // host's arithmetic), so that one transfer of 6 reals per body comes back.
  virtual void body_loads(const std::vector<Vec3>& centre, std::vector<Wrench>& out) const = 0;

  // Returns once the device has done all the work asked of it so far, for timing each stage
  // on its own (a GPU runs the loops while the host goes on).
  virtual void finish() const = 0;

  // Whether a particle went wrong (particle_check.hpp); the host's copy then names it.
  virtual bool any_problem() const = 0;
  // Keeps the present state of the fields a frame shows as the last good one (on the device),
  // and copies it back into a set of the host's fields.
  virtual void remember() = 0;
  virtual void download_remembered(ParticleSet<D>& host) const = 0;
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
