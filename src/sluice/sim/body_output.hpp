// Time series of the rigid bodies: OUT/bodies/NAME.csv per body (pose, velocities, the fluid's
// and the contacts' force and moment), OUT/loads.csv (the fluid's force on each body and on all
// of them as drag, lift and side force) and OUT/energy.csv (docs/output.md). A row's forces
// and moments are their means over the steps since the row before, weighted by each step's
// length: the impulse over the interval divided by it. The step that lands on a row's time is
// shortened, and a shortened step's load can be far from the steps' around it (a constraint
// fluid's drag on the fording vehicle reads near 0 N there against 200-500 N on the others).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sluice/coupling/coupler.hpp"
#include "sluice/fluid/fluid_energy.hpp"
#include "sluice/io/csv_writer.hpp"
#include "sluice/sim/rigid_bodies.hpp"

namespace sluice {

class BodyOutput {
 public:
  // Creates OUT/bodies and the files (only energy.csv when there are no bodies). Drag is the
  // fluid's force against `travel` (unit, horizontal), lift along -gravity, side along
  // up x travel (3D only).
  BodyOutput(const std::string& out_dir, const RigidBodies& bodies, const Vec3& travel,
             const Vec3& gravity, int dimension, io::CsvStart start = io::CsvStart::kNew);

  // Adds the loads of a step of `dt` seconds, just taken, to the interval's sums.
  void accumulate(double dt, const RigidBodies& bodies, const Coupler& coupler);
  // Writes a row: the sums' means (at t = 0, where no step has been taken, the loads as they
  // stand), and starts the next interval.
  void record(double time, const RigidBodies& bodies, const Coupler& coupler,
              const FluidEnergy& fluid);
  // Checkpoints: the files' lengths.
  void archive_state(StateArchive& a);

 private:
  std::vector<std::unique_ptr<io::CsvWriter>> body_csv_;
  std::unique_ptr<io::CsvWriter> loads_csv_;
  std::unique_ptr<io::CsvWriter> energy_csv_;
  Vec3 drag_axis_, lift_axis_, side_axis_;  // drag_axis_ = -travel
  // Per body, the time integrals since the last row of the fluid's force and moment and of the
  // contacts' force and moment, and the time they span.
  std::vector<Vec3> fluid_force_, fluid_moment_, contact_force_, contact_moment_;
  double span_ = 0;
  bool with_side_ = true;
};

}  // namespace sluice
