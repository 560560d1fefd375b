// A penalty-sph run whose particles live in a device's memory for the whole run (issue 41): the
// particle base's device (particle_device.hpp) with penalty-sph's stages, which the model calls
// each step. The stages run the loop bodies the host runs (penalty_sph_loop_bodies.hpp,
// penalty_drift.hpp) through a backend: the host's own threads over the device's arrays
// ("emulated"), which tests the run's bookkeeping on machines without a GPU. The solids are
// gathered, sorted and gridded there; the drift's scratch is bounded (BoundedDriftScratch); the
// impulses on the body points are summed there in particle order, as the host sums them.
#pragma once

#include <memory>
#include <vector>

#include "sluice/fluid/particle_device.hpp"
#include "sluice/fluid/particle_device_run.hpp"
#include "sluice/fluid/penalty_sph/penalty_drift.hpp"
#include "sluice/fluid/penalty_sph/penalty_sph_loop_bodies.hpp"

namespace sluice {

// What the stages need besides the particles, as penalty_sph_model.hpp sets it.
template <int D>
struct PenaltySphDeviceSetup {
  ParticleDeviceSetup<D> base;
  PenaltySphConstants<D> constants;
  SolidContactSettings<D> contact;
  Real fluid_spacing = 0;  // l0
};

template <int D>
class PenaltySphDeviceRun : public ParticleDevice<D> {
 public:
  using Totals = typename PenaltyStepCounters<D>::Totals;

  virtual void half_kick(Real dt) = 0;  // PenaltyHalfKick
  virtual void kick(Real dt) = 0;       // PenaltyKick
  virtual void density() = 0;           // PenaltyDensity
  virtual void forces() = 0;            // PenaltyForces
  // Minus the pressure force each body particle exerts on its fluid neighbours, into `force`
  // (one per body point; PenaltyBodyPressureForce).
  virtual void body_pressure_forces(std::vector<Vec<D>>& force) = 0;
  virtual Real max_speed() const = 0;
  virtual Real max_acceleration() const = 0;

  // The drift (penalty_sph_model.hpp's kick_drift and advance_with_bodies). The walls and fixed
  // solid layers, gathered once: they never move.
  virtual void gather_fixed_solids() = 0;
  // Starts the step's drift of dt, after the half kick. Without bodies every fluid particle
  // drifts now; with them, their particles stand where they are, the fluid particles out of
  // their reach over the whole step drift now, and the others wait for the exchanges.
  virtual void start_drift(Real dt, bool with_bodies) = 0;
  // One exchange: the bodies have advanced by dt; the fluid particles in their reach drift by
  // dt against them, and `impulse` gets the drift's impulse on each body point.
  virtual void drift_with_bodies(Real dt, std::vector<Vec<D>>& impulse) = 0;
  // The step's drift of dt is done: the end-of-step velocity and boundary force
  // (PenaltyEndOfDrift), and the step's counters.
  virtual Totals finish_drift(Real dt) = 0;
  // 1/2 Ks d^2 over the fluid-solid pairs in contact now (PenaltyElasticEnergy).
  virtual double elastic_energy() const = 0;
};

// The run on the emulated device (the host's threads).
template <int D>
std::unique_ptr<PenaltySphDeviceRun<D>> make_penalty_sph_emulated_run(
    const PenaltySphDeviceSetup<D>& setup);

}  // namespace sluice
