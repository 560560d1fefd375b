// The grid model (seed 001's third method): inviscid incompressible flow (a viscous term
// where the case asks for one) on a staggered MAC grid by a projection method. A step:
// advect the level set and the velocity (MacCormack), correct the level set by its marker
// particles and reinitialise it, add gravity and viscosity, place the bodies, project, and
// extend the velocity into the air. A free body's velocity is solved with the pressure, and its
// load is the pressure on its cut faces; coupled by the projection scheme, the bodies take that
// velocity (coupling/coupling_scheme.hpp).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sluice/coupling/body_geometry.hpp"
#include "sluice/fluid/fluid_system.hpp"
#include "sluice/fluid/mac/free_surface.hpp"
#include "sluice/fluid/mac/mac_parameters.hpp"
#include "sluice/fluid/mac/pressure_projection.hpp"
#include "sluice/fluid/mac/solid_boundary.hpp"
#include "sluice/io/case_config.hpp"

namespace sluice {

template <int D>
class MacModel : public FluidSystem,
                 public FluidExchange,
                 public FluidObservation,
                 public FluidGuard {
 public:
  MacModel(const MacParameters& parameters, const io::CaseConfig& config,
           const BodyGeometry& bodies);

  FluidExchange& exchange() override { return *this; }
  const FluidObservation& observation() const override { return *this; }
  FluidGuard& guard() override { return *this; }

  std::string describe() const override;
  void append_stages(StageList& before_bodies, StageList& after_bodies) override;
  TimeStep next_time_step() const override;
  void receive_body_motion(const std::vector<BodyKinematics>& motion) override;
  // The pressure's loads of the last projection and the viscous stress's of the last step.
  std::vector<Wrench> body_loads(const std::vector<BodyKinematics>& motion) const override;
  void solve_body_velocities() override { solves_body_velocities_ = true; }
  std::vector<Vec6> solved_body_velocities() const override { return solved_velocities_; }

  FluidView view() const override { return view_of(surface_.phi(), now_); }
  double pressure_at(const Vec3& x) const override;
  double water_height_at(const Vec3& gauge) const override;
  double surge_front(int axis) const override;
  double boundary_flux(std::size_t index) const override;
  std::optional<std::string> check(const StepClock& clock) const override;
  void remember_good(double time) override;
  FluidView last_good_view() const override { return view_of(last_good_.phi, last_good_); }
  double last_good_time() const override { return last_good_time_; }
  FluidSize size() const override;
  FluidEnergy energy() const override;
  std::vector<std::pair<std::string, double>> counters() const override;
  double interaction_radius() const override { return grid_.h; }
  // The velocities, pressures and valid faces, the surface with its markers, the projection's
  // warm start and the loads it held; read back, the bodies are placed in the grid again.
  void archive_state(StateArchive& a) override;

  const MacGrid<D>& grid() const { return grid_; }
  const CellField& level_set() const { return surface_.phi(); }
  const CellField& pressure() const { return now_.pressure; }
  const FaceField<D>& velocity() const { return now_.u; }
  // The water's volume (2D: area) from the level set, each cell by its smeared fraction.
  double water_volume() const;
  const ProjectionReport& last_projection() const { return last_projection_; }

 private:
  struct Fields {
    CellField phi;       // the level set (a copy of surface_'s, for the last good state)
    FaceField<D> u;      // velocity components on the faces
    CellField pressure;  // [Pa], carried into solid cells next to the water
  };

  void advect(double dt);
  // The face velocities with each face partly within a solid at its mean over the face.
  FaceField<D> flux_velocity() const;
  // The level set beside the inlets: their water.
  void fill_inflow();
  void add_forces(double dt);
  // Explicit diffusion of each velocity component, no slip on the solids; the bodies' share
  // of the momentum it moves becomes their viscous load.
  void diffuse(double dt);
  // `moving`: the bodies' velocities are unknowns of the projection; else the bodies hold
  // still. Coupled by held loads, the bodies advanced with the last step's loads, which are
  // taken out of their velocities first; in the projection scheme they advanced without them,
  // and answer through their joined mobility.
  void project(double dt, bool moving = true);
  void extend();
  // The surface of `phi` as points, and the cells with their fields.
  FluidView view_of(const CellField& phi, const Fields& f) const;
  bool is_water(std::size_t cell) const {
    return surface_.phi()[cell] < 0 && !solid_.cell_is_solid(cell);
  }

  MacParameters p_;
  MacGrid<D> grid_;
  std::string solver_;  // the pressure solver's name, `auto` resolved
  Vec<D> gravity_;
  Real density_;
  Real viscosity_;
  const BodyGeometry& geometry_;
  SolidBoundary<D> solid_;
  PressureProjection<D> projection_;
  FreeSurface<D> surface_;
  std::vector<BodyKinematics> motion_;
  std::vector<Wrench> loads_;            // the pressure's on each body, from the last projection
  std::vector<Wrench> viscous_loads_;    // the viscous stress's on each body, from the last step
  bool solves_body_velocities_ = false;  // the projection scheme
  std::vector<Vec6> solved_velocities_;  // the bodies', from the last projection (that scheme)
  // Each face's relaxation rate [1/s] in the case's damping zones (none: empty).
  FaceField<D> damping_rate_;
  Fields now_;
  FaceMarks<D> valid_;
  Fields last_good_;
  double last_good_time_ = 0;
  ProjectionReport last_projection_;
  double projections_ = 0, pressure_iterations_ = 0, unconverged_ = 0;
  double releases_ = 0;     // projections made again with a contact let go
  double restored_ = 0;     // water volume the volume correction gave back (negative: took)
  double held_volume_ = 0;  // the water the volume correction keeps (2D: area)
};

}  // namespace sluice
