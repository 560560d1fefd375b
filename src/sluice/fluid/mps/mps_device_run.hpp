// An MPS run whose particles live in a device's memory for the whole run (issue 41): the
// particle base's device (particle_device.hpp, which the base owns and runs its own services
// on) with mps's stages, which the model calls each step. The stages run the loop bodies the
// host runs (mps_loop_bodies.hpp, pressure_rows.hpp) through a backend: the host's
// own threads over the device's arrays ("emulated"), which tests the device run's bookkeeping
// (sort, scans, neighbour list, numbering of the unknowns, transfers) on machines without a GPU.
// The pressure solve is the host's sparse solver on the assembled rows.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "sluice/fluid/mps/mps_operators.hpp"
#include "sluice/fluid/mps/pressure_rows.hpp"
#include "sluice/fluid/particle_device.hpp"
#include "sluice/fluid/particle_device_run.hpp"
#include "sluice/linear/sparse_solver.hpp"

namespace sluice {

// What the stages need besides the particles: the operators' weights and lattices, and the
// model's settings, as mps_model.hpp sets them.
template <int D>
struct MpsDeviceSetup {
  ParticleDeviceSetup<D> base;
  MpsWeight weight, laplacian_weight;
  MpsLatticeConstants lattice, laplacian_lattice;
  bool gradient_correction = true;
  Real neighbour_radius = 0;  // the list's radius: the cells'
  bool extrapolated_walls = true;
  Real collision_reach = 0;  // 0: no collisions
  Real collision_restitution = 0;
  Vec<D> gravity = Vec<D>::Zero();
  Real density = 0;
  Real surface_density = 0, surface_count = 0;  // beta n0 and the count's bar
  Real minimum_density = 0;                     // the gradient's: minimum_density n0
  std::string solver;
  SolverSettings solver_settings;
};

template <int D>
class MpsDeviceRun : public ParticleDevice<D> {
 public:
  // The stages of a step, in the model's order (the base's neighbour stage after predict).
  virtual void predict(Real dt, Real nu) = 0;  // the prediction, then the collisions
  virtual void build_neighbours() = 0;
  virtual void find_surface() = 0;
  virtual void state_equation(Real stiffness) = 0;  // the explicit variant's pressure
  // The pressure equation's rows (pressure_equation.hpp; the extrapolated walls' inputs first),
  // with its source relaxation gamma, compressibility alpha and memory m.
  virtual void assemble(Real dt, Real relaxation, Real compressibility, bool pressure_memory) = 0;
  // Solves from the last pressure and writes the new one; false where the solver fell short.
  virtual bool solve() = 0;
  virtual const PressureEquationReport& report() const = 0;
  virtual void clamp_negative() = 0;
  virtual void correct(Real dt) = 0;
  virtual Real max_speed() const = 0;
  // Which particles the fluid reaches (one per particle, the device's order), for the bodies'
  // loads on the host.
  virtual void download_active(std::vector<std::uint8_t>& active) const = 0;
  // The neighbour list (NeighbourList's starts and indices), for checkpoints: the next step's
  // prediction reads the last one.
  virtual void download_neighbours(std::vector<std::uint32_t>& start,
                                   std::vector<std::uint32_t>& index) const = 0;
  virtual void upload_neighbours(const std::vector<std::uint32_t>& start,
                                 const std::vector<std::uint32_t>& index) = 0;
};

// The run on the emulated device (the host's threads).
template <int D>
std::unique_ptr<MpsDeviceRun<D>> make_mps_emulated_run(const MpsDeviceSetup<D>& setup);

}  // namespace sluice
