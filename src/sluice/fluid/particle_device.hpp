// Where the particle base's particles live when not on the host: a device that holds them for
// the whole run and runs the base's services on them (the neighbour stage, the body points, the
// check, the last good state, the energy). ParticleFluid calls it in place of its host path;
// the host's set is then a cache that it refreshes from the device before anything reads it.
// Implemented over a backend by particle_device_run.hpp (ParticleDeviceOn); a model whose
// stages run on the device extends it with them (wcsph's WcsphDeviceRun).
#pragma once

#include <string>
#include <vector>

#include "sluice/core/types.hpp"
#include "sluice/fluid/fluid_energy.hpp"
#include "sluice/particles/particle_set.hpp"

namespace sluice {

template <int D>
class ParticleDevice {
 public:
  virtual ~ParticleDevice() = default;
  // What runs it, for the run's header: the GPU's name, or "emulated".
  virtual std::string name() const = 0;
  // Bytes of device memory per particle (its fields, the sort's scratch, the last good state).
  virtual double bytes_per_particle() const = 0;

  // Copies every field of `host` (whatever its fields: the device's set mirrors the host's
  // labels), the body points' accelerations and the cells of the host's last sort
  // (`cell_start`, CellList's) to the device, or back. The device's order and cells are the
  // host's after an upload (read back from a checkpoint, the particles have moved since that
  // sort, and a sort here could reorder them); after a download the host holds the device's
  // order, sorted by cell as of the step's neighbour sort.
  virtual void upload(const ParticleSet<D>& host, const std::vector<Vec3>& point_acceleration,
                      const std::vector<std::uint32_t>& cell_start) = 0;
  virtual void download(ParticleSet<D>& host, std::vector<Vec3>& point_acceleration) const = 0;
  // The cells of the device's last sort (CellList's starts), which the downloaded particles
  // are in: a stage after the sort may move a particle out of its cell (mps's correction), and
  // the host then reads them as the host's own run would have.
  virtual void download_cell_starts(std::vector<std::uint32_t>& start) const = 0;

  // The neighbour stage: puts back fluid found in a wall's layers (wall_surfaces.hpp), then
  // sorts by cell.
  virtual void sort_by_cell() = 0;
  // The bodies moved: `body_motion` holds each body's kinematics (pack_body_motion); the device
  // places their points (rigid_point.hpp, the host's arithmetic) and their particles.
  virtual void set_body_motion(const std::vector<Real>& body_motion) = 0;
  // The fluid's kinetic and potential energy and mass (fluid_energy.hpp), summed on the device
  // (energy.csv's rows cost no transfer of the particles). `gravity` holds D reals.
  virtual FluidEnergy energy(const Real* gravity) const = 0;
  // Whether a particle went wrong (particle_check.hpp); the host's copy then names it.
  virtual bool any_problem() const = 0;
  // Keeps the present state of the fields a frame shows as the last good one (on the device),
  // and copies it back into a set of the host's fields.
  virtual void remember() = 0;
  virtual void download_remembered(ParticleSet<D>& host) const = 0;

  // Returns once the device has done all the work asked of it so far (a GPU runs the loops
  // while the host goes on). With time_stages, the base calls it after each of its stages, so
  // that a stage's time is its own work's (model.time_device_stages).
  virtual void finish() const = 0;
  bool time_stages = false;
};

}  // namespace sluice
