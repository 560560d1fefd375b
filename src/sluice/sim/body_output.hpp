// Time series of the rigid bodies: OUT/bodies/NAME.csv per body (pose, velocities, the fluid's
// and the contacts' force and moment) and OUT/energy.csv (docs/output.md).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sluice/io/csv_writer.hpp"
#include "sluice/sim/rigid_bodies.hpp"

namespace sluice {

struct FluidEnergy {
  double kinetic = 0;
  double potential = 0;  // relative to z = 0 along -g, as the bodies'
};

class BodyOutput {
 public:
  // Creates OUT/bodies and the files (nothing when there are no bodies).
  BodyOutput(const std::string& out_dir, const RigidBodies& bodies);

  void record(double time, const RigidBodies& bodies, const FluidEnergy& fluid);

 private:
  std::vector<std::unique_ptr<io::CsvWriter>> body_csv_;
  std::unique_ptr<io::CsvWriter> energy_csv_;
};

}  // namespace sluice
