// The base of the particle models: it owns the particles and their neighbour grid, fills the
// fluid blocks, samples the walls in layers as thick as the model's support and places
// particles in the bodies; it moves the body particles with the bodies, sums the model's forces
// on them into loads, and answers output, probes and the divergence check from the particles.
// A model adds its fields, its stages and its forces on the body particles. The particles live
// on the host, or on a device (particle_device.hpp) where the base runs its own services and
// keeps the host's set as a cache.
#pragma once

#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "sluice/coupling/body_geometry.hpp"
#include "sluice/coupling/body_points.hpp"
#include "sluice/exec/host_backend.hpp"
#include "sluice/exec/policy.hpp"
#include "sluice/fluid/fluid_system.hpp"
#include "sluice/fluid/particle_device_run.hpp"
#include "sluice/fluid/particle_open_boundaries.hpp"
#include "sluice/fluid/particle_state.hpp"
#include "sluice/fluid/wall_surfaces.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/parallel/communicator.hpp"
#include "sluice/parallel/particle_exchange.hpp"

namespace sluice {

// Number of boundary-particle layers needed behind a wall for a given interaction radius.
inline int wall_layers(Real interaction_radius, Real dx) {
  return static_cast<int>(std::ceil(interaction_radius / dx - 1e-9));
}

// The case's open boundaries and damping zones run on the CPU for now: a particle model whose
// loops are to run on a device (`on_device`) refuses a case with either (InputError at
// model.device).
void refuse_device_with_open_water(const io::CaseConfig& config, bool on_device);

template <int D>
class ParticleFluid : public FluidSystem,
                      public FluidExchange,
                      public FluidObservation,
                      public FluidGuard {
 public:
  // How the model's fluid meets the case's walls: through layers of wall particles as thick as
  // its support, or through the walls' surfaces alone (a granular fluid's spheres), with no
  // wall particle.
  enum class Walls { kParticleLayers, kSurfacesOnly };

  // Builds the particles, sorted by cell: fluid (none inside walls or bodies), walls, and the
  // bodies' particles (with `interaction_radius` > 0, layers under each body's surface; else
  // its surface particles, for a case of bodies alone). Throws InputError when the case has
  // fluid blocks but no fluid particle remains.
  ParticleFluid(const io::CaseConfig& config, Real interaction_radius, const BodyGeometry& bodies,
                Walls walls = Walls::kParticleLayers);

  ParticleState<D>& state() { return state_; }
  const ParticleState<D>& state() const { return state_; }
  const BodyPoints& body_points() const { return body_points_; }
  std::size_t body_count() const { return body_count_; }
  const WallSurfaces& wall_surfaces() const { return wall_surfaces_; }

  // Called once after construction: the model's fields and what its first step needs.
  virtual void initialize() = 0;

  // From here on the particles live in the emulated device's memory (exec/host_backend.hpp):
  // the base's services run there (particle_device_run.hpp), and so do a model's loops written
  // with for_each_particle; the host's set becomes a cache that refresh_host() fills before
  // anything reads it. Called after initialize(). (A GPU run needs the model's loop bodies
  // compiled for it: wcsph has its own device run.)
  void run_on_emulated_device();

  // From here on the particles are split over `ranks` (called before initialize(), on every
  // rank, each of which built the whole case; with one rank, nothing happens unless the case
  // has a periodic axis, whose images are ghosts as another rank's particles are): slabs along the
  // domain's longest horizontal axis, or the boxes of Zoltan's RCB where the case's
  // `ranks.partition` says rcb, with an equal share of the particles' work each; every rank keeps
  // its own and, as ghosts, copies of the others' within `halo_depth` of its region, taken anew at
  // each neighbour stage. Counts, sums, probes, loads and the check are then over the run's ranks;
  // a frame holds this rank's own particles.
  void distribute(const Communicator& ranks, Real halo_depth);
  std::string decomposition() const override;
  // Resuming a checkpoint written on another number of ranks (collective): between
  // begin_gathering and end_gathering, archive_state reads one writing rank's piece at a time,
  // keeps the particles that rank owned and hands the model's state to gather_model; then
  // end_gathering splits the whole case anew over this run's ranks, as distribute() did, and
  // the model rebuilds what indexes its particles (redistributed()).
  void begin_gathering(int written_ranks) override;
  void end_gathering() override;

  // Stages: the model's first stages; then, after the bodies' advance, the engine's neighbour
  // sort and the model's other stages.
  void append_stages(StageList& before_bodies, StageList& after_bodies) override;
  void receive_body_motion(const std::vector<BodyKinematics>& motion) override;
  std::vector<Wrench> body_loads(const std::vector<BodyKinematics>& motion) const override;

  FluidExchange& exchange() override { return *this; }
  const FluidObservation& observation() const override { return *this; }
  FluidGuard& guard() override { return *this; }

  FluidView view() const override;
  double pressure_at(const Vec3& x) const override;
  double water_height_at(const Vec3& gauge) const override;
  double surge_front(int axis) const override;
  double boundary_flux(std::size_t index) const override;
  std::optional<std::string> check(const StepClock& clock) const override;
  void remember_good(double time) override;
  FluidView last_good_view() const override;
  double last_good_time() const override { return last_good_time_; }
  FluidSize size() const override;
  FluidEnergy energy() const override;  // kinetic, potential and mass of the fluid
  double interaction_radius() const override { return radius_; }
  // On several ranks: the ghosts and migrants an exchange, and the seconds of waiting for the
  // other ranks, of migration, halo and balance (each the largest rank's); none on one.
  std::vector<std::pair<std::string, double>> counters() const override;
  // The particles (every field), the cells of the last sort, and then the model's own state.
  void archive_state(StateArchive& a) override;

 protected:
  // The model's state beyond its particle fields (archive_state).
  virtual void archive_model(StateArchive& a) = 0;
  // Resuming on another number of ranks: reads one piece's archive_model state (the `first`
  // piece's, or a later one's) and folds it into this rank's: a largest value over the
  // writing ranks' is the largest of the pieces', a sum of their shares their sum (held by the
  // first rank alone, where the ranks' counts are summed again). A model that never splits
  // leaves it: its checkpoints are one rank's.
  virtual void gather_model(StateArchive& a, bool first);
  // After end_gathering reordered the particles: rebuilds what indexes them.
  virtual void redistributed() {}
  // Who changed sides at the open boundaries this step (particle_open_boundaries.hpp), before
  // the neighbour sort: a model whose particles carry state of their own beyond the engine's
  // fields (half-step values, roles) sets it up for them.
  virtual void handed_over(const BufferHandOver& /*hand_over*/) {}
  // After the model's boundary state (its walls' pressure): the pressure and density, as the
  // model's equation of state gives it by density_of(p), of each outlet buffer particle whose
  // outlet prescribes one (ParticleOpenBoundaries::prescribe_outlet_pressure).
  template <class DensityOf>
  void prescribe_outlet_pressure(DensityOf&& density_of, Real surface_shift = 0) {
    if (!open_.empty())
      open_.prescribe_outlet_pressure(state_.particles, open_zone_, density_of, surface_shift);
  }
  // The model's stages around the neighbour sort.
  virtual void model_stages(StageList& before_neighbours, StageList& after_neighbours) = 0;
  // The fluid's force on every body particle (kind kBody), indexed by its body point, from the
  // last force evaluation, for the bodies' present `motion`. `force` has one entry per body
  // point, zero on entry.
  virtual void body_point_forces(const std::vector<BodyKinematics>& motion,
                                 std::vector<Vec3>& force) const = 0;
  // Whether body_point_forces reads the particle set (else a device's particles are not copied
  // back for it, at each exchange with the bodies).
  virtual bool body_forces_read_particles() const { return true; }
  // On several ranks: whether body_point_forces gives this rank's share of every body point's
  // force (what its own fluid particles put on the point, ghost points too), which adds up over
  // the ranks as it is; else it gives the whole force at each point this rank owns, and a ghost
  // point's is dropped.
  virtual bool body_point_forces_are_rank_shares() const { return false; }
  // A model whose particles live elsewhere (on a device) copies them into the particle set
  // here; whatever reads the particle set (output, probes, the check, checkpoints) calls it
  // first. The base copies the emulated device's particles back; nothing otherwise.
  virtual void refresh_host() const;

  // body(i) for every particle, wherever the particles live: make(set) builds the loop body
  // from a set's field components (set.template components<Real>("pressure") ...), the host's
  // ParticleSet or the emulated device's DeviceParticleSet, so that a model's loops run on
  // either without code of their own for the device.
  // (On a device other than the emulated one a model runs its own device run's stages.)
  template <class Make>
  void for_each_particle(Make&& make) {
    if (emulated_loops_) {
      emulated_loops_->for_each(make(emulated_loops_->particles()));
      host_current_ = false;
    } else {
      if (device_)
        throw std::logic_error("for_each_particle: this model has no loops for " + device_->name());
      exec::Default::for_each(state_.particles.size(), make(state_.particles));
    }
  }

  // From here on the particles live on `device`, uploaded from the host's set: the base's
  // services run there, and the host's set is a cache. A model with stages of its own on the
  // device keeps a pointer to it and runs them with on_device.
  void run_on_device(std::unique_ptr<ParticleDevice<D>> device);
  const ParticleDevice<D>* device() const { return device_.get(); }
  // Runs `work` on the device: the host's set is stale after it; with the device's time_stages,
  // waits for the work to finish (so that the stage's time is its own).
  template <class Work>
  void on_device(Work&& work) const {
    work();
    if (device_->time_stages) device_->finish();
    host_current_ = false;
  }

  // The kinds that a count or a largest value over the particles reads (ParticleKind's
  // integers): a ghost's is -1, so that only its owner counts it.
  const std::int32_t* counted_kinds() const;
  const Communicator& ranks() const { return ranks_; }
  // Split, collective: the ghosts' `fields` (arrays over the particle set) as their owners hold
  // them now (ParticleExchange::refresh); one rank alone, nothing.
  template <class... T>
  void refresh_ghosts(std::vector<T>&... fields) const {
    if (exchange_) exchange_->refresh(fields...);
  }
  // How many times the ranks' cuts have moved (shift balancing): what this rank owns of the
  // walls changes with them.
  int cut_moves() const { return exchange_ ? exchange_->totals().balances : 0; }

  // The neighbours stage: puts back fluid found in a wall's layers, then sorts the particle
  // set by cell.
  virtual void sort_by_cell();
  FluidView view_of(const ParticleSet<D>& particles) const;
  // What the particle base's services need to run on a device (particle_device_run.hpp): the
  // cells, the body points, the walls, the escape box and the carried velocity's field.
  ParticleDeviceSetup<D> device_setup() const;
  // A model whose step goes on from a half-step velocity after the neighbour stage names it
  // here, so that a particle put back on a wall loses its speed into the wall there too.
  void carry_through_put_back(FieldHandle<Vec<D>> half_step_velocity) {
    carried_velocity_ = half_step_velocity;
  }

 private:
  // Puts back on a wall's surface, with its velocity into the wall taken away, a fluid particle
  // found within the wall's particle layers: one squeezed through where a body rests on the
  // wall (the gap under a wheel is thinner than a spacing), which the layers' pressure alone
  // does not always hold. Deeper than the layers it is left alone (a wall is a plane without
  // end here, so a particle beyond its far side is not in it).
  void keep_out_of_walls();
  // The neighbours stage's first part with open boundaries: the buffers' particles moved on and
  // handed over (particle_open_boundaries.hpp); those that left the domain are dropped by the
  // sort after it.
  void pass_open_boundaries(const StepClock& clock);
  // The damping zones' stage, after the model's last: each fluid particle's velocity times
  // exp(-rate dt), the rates of the zones it lies in added up.
  void damp(Real dt);

  Real radius_;
  WallSurfaces wall_surfaces_;
  ParticleState<D> state_;
  BodyPoints body_points_;
  std::size_t body_count_ = 0;
  std::vector<std::uint32_t> order_;  // scratch of the neighbour sort
  std::optional<FieldHandle<Vec<D>>> carried_velocity_;
  // With open boundaries: the buffers, each particle's (its `open_boundary` field), and the last
  // pass's particles to drop and who changed sides.
  std::vector<io::DampingZone> damping_;
  ParticleOpenBoundaries<D> open_;
  FieldHandle<std::int32_t> open_zone_;
  std::vector<bool> open_gone_;
  BufferHandOver hand_over_;
  ParticleSet<D> last_good_;
  double last_good_time_ = 0;
  // With run_on_device: the device, and whether the host's set holds its state; with
  // run_on_emulated_device, the base's run there, which runs the model's loops too.
  std::unique_ptr<ParticleDevice<D>> device_;
  ParticleDeviceRun<D, exec::HostBackend>* emulated_loops_ = nullptr;
  mutable bool host_current_ = true;
  // With distribute(): the run's ranks and the particles' traffic between them.
  Communicator ranks_ = Communicator::alone();
  std::unique_ptr<ParticleExchange<D>> exchange_;
  // The case's periodic axis, if any, and where the case names it.
  std::optional<PeriodicSpan> periodic_;
  std::string periodic_key_;
  std::pair<std::string, int> periodic_place_;
  // Reads the case's periodic axis, and drops the walls' particles past its sides.
  void join_periodic_sides(const io::CaseConfig& config, std::vector<Vec<D>>& walls);
  FieldHandle<std::int32_t> owned_kind_;
  bool rcb_ = false;  // the regions: Zoltan's RCB boxes, not slabs
  // distribute()'s split of the whole case over the ranks, at the balance's first cuts.
  void split_evenly(Real halo_depth);
  // Between begin_gathering and end_gathering: the pieces' own particles, how many pieces were
  // read and how many ranks wrote them.
  void gather_piece(StateArchive& a);
  std::optional<ParticleSet<D>> gathered_;
  int gathered_pieces_ = 0, written_ranks_ = 1;
  // Of the state's particles, those this rank owns, with the fields for which keep(label)
  // holds (a frame, the guard's last good state).
  ParticleSet<D> owned_particles(bool (*keep)(const FieldLabel&)) const;
  // `problem` (empty: none) of the first rank that has one, on every rank.
  std::optional<std::string> first_problem(const std::string& problem) const;
};

}  // namespace sluice
