// Time series of the rigid bodies: OUT/bodies/NAME.csv per body (pose, velocities, the fluid's
// and the contacts' force and moment) and OUT/energy.csv (docs/output.md).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sluice/coupling/coupler.hpp"
#include "sluice/fluid/fluid_system.hpp"
#include "sluice/io/csv_writer.hpp"
#include "sluice/sim/rigid_bodies.hpp"

namespace sluice {

class BodyOutput {
 public:
  // Creates OUT/bodies and the files (nothing when there are no bodies).
  BodyOutput(const std::string& out_dir, const RigidBodies& bodies);

  void record(double time, const RigidBodies& bodies, const Coupler& coupler,
              const FluidEnergy& fluid);

 private:
  std::vector<std::unique_ptr<io::CsvWriter>> body_csv_;
  std::unique_ptr<io::CsvWriter> energy_csv_;
};

}  // namespace sluice
