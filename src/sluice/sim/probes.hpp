// Measurements along the run, written to OUT/probes.csv: point pressure (Shepard-interpolated
// from the fluid), water height on a vertical gauge line, and the surge front.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sluice/fluid/particle_state.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/io/csv_writer.hpp"

namespace sluice {

template <int D>
class Probes {
 public:
  // Opens the CSV file when the case has probes and `csv_path` is not empty; `radius` is the
  // fluid model's support.
  Probes(const std::vector<io::ProbeConfig>& probes, const std::string& csv_path, Real radius);

  bool empty() const { return probes_.empty(); }
  // Appends one row for the state's time.
  void record(const ParticleState<D>& s);
  // The values of one row, in the order of the case's probes (used by tests too).
  std::vector<double> measure(const ParticleState<D>& s) const;

 private:
  Real pressure_at(const ParticleState<D>& s, const Vec<D>& x) const;
  Real water_height_at(const ParticleState<D>& s, const Vec3& gauge) const;
  Real surge_front(const ParticleState<D>& s, int axis3) const;

  std::vector<io::ProbeConfig> probes_;
  Real radius_;
  std::unique_ptr<io::CsvWriter> csv_;
};

}  // namespace sluice
