// Measurements along the run, written to OUT/probes.csv: point pressure (Shepard-interpolated
// from the fluid), water height on a vertical gauge line, and the surge front.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sluice/io/case_config.hpp"
#include "sluice/io/csv_writer.hpp"
#include "sluice/sim/state.hpp"

namespace sluice {

template <int D>
class Probes {
 public:
  // Opens the CSV file when the case has probes and `csv_path` is not empty; `radius` is the
  // fluid model's support.
  Probes(const std::vector<io::ProbeConfig>& probes, const std::string& csv_path, Real radius);

  bool empty() const { return probes_.empty(); }
  // Appends one row for the state's time.
  void record(const SimulationState<D>& s);
  // The values of one row, in the order of the case's probes (used by tests too).
  std::vector<double> measure(const SimulationState<D>& s) const;

 private:
  Real pressure_at(const SimulationState<D>& s, const Vec<D>& x) const;
  Real water_height_at(const SimulationState<D>& s, const Vec3& gauge) const;
  Real surge_front(const SimulationState<D>& s, int axis3) const;

  std::vector<io::ProbeConfig> probes_;
  Real radius_;
  std::unique_ptr<io::CsvWriter> csv_;
};

}  // namespace sluice
