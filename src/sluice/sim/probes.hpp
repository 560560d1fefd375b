// Measurements along the run, written to OUT/probes.csv: point pressure, water height on a
// vertical gauge line, and the surge front, each as the fluid answers it.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "sluice/fluid/fluid_observation.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/io/csv_writer.hpp"

namespace sluice {

class Probes {
 public:
  // Opens the CSV file when the case has probes and `csv_path` is not empty (kContinue: the
  // file of a resumed run).
  Probes(const std::vector<io::ProbeConfig>& probes, const std::string& csv_path,
         io::CsvStart start = io::CsvStart::kNew);

  bool empty() const { return probes_.empty(); }
  // Appends one row for the time, to the file and, after keep_record(), to recorded().
  void record(double time, const FluidObservation& fluid);
  // From now on, recorded() keeps every row (for a caller that steps the run and reads them;
  // a long run's command line keeps none, its memory bounded).
  void keep_record() { keep_record_ = true; }
  // The rows kept since keep_record(): the time, then each probe's value.
  const std::vector<std::vector<double>>& recorded() const { return recorded_; }
  // Each probe's column label, its name and unit: "front [m]", "P1 [Pa]".
  std::vector<std::string> labels() const;
  // The values of one row, in the order of the case's probes (used by tests too).
  std::vector<double> measure(const FluidObservation& fluid) const;
  // Checkpoints: the CSV file's length.
  void archive_state(StateArchive& a) {
    if (csv_) csv_->archive_state(a);
  }

 private:
  std::vector<io::ProbeConfig> probes_;
  std::unique_ptr<io::CsvWriter> csv_;
  bool keep_record_ = false;
  std::vector<std::vector<double>> recorded_;
};

}  // namespace sluice
