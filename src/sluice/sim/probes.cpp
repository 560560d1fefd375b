#include "sluice/sim/probes.hpp"

namespace sluice {

Probes::Probes(const std::vector<io::ProbeConfig>& probes, const std::string& csv_path,
               io::CsvStart start)
    : probes_(probes) {
  if (probes_.empty() || csv_path.empty()) return;
  std::vector<std::string> header{"time [s]"};
  for (const std::string& label : labels()) header.push_back(label);
  csv_ = std::make_unique<io::CsvWriter>(csv_path, header, start);
}

std::vector<std::string> Probes::labels() const {
  std::vector<std::string> out;
  for (const auto& p : probes_) {
    out.push_back(p.name + " [" + p.unit + "]");
  }
  return out;
}

std::vector<double> Probes::measure(const FluidObservation& fluid) const {
  std::vector<double> row;
  for (const auto& p : probes_) {
    switch (p.kind) {
      case io::ProbeKind::kPressure:
        row.push_back(fluid.pressure_at(p.point));
        break;
      case io::ProbeKind::kWaterHeight:
        row.push_back(fluid.water_height_at(p.point));
        break;
      case io::ProbeKind::kSurgeFront:
        row.push_back(fluid.surge_front(p.axis));
        break;
      case io::ProbeKind::kBoundaryFlux:
        row.push_back(fluid.boundary_flux(p.boundary));
        break;
    }
  }
  return row;
}

void Probes::record(double time, const FluidObservation& fluid) {
  if (probes_.empty()) return;
  // Measured on every rank (the readings add up over them), written where the file is.
  const std::vector<double> values = measure(fluid);
  std::vector<double> row{time};
  row.insert(row.end(), values.begin(), values.end());
  if (csv_) csv_->row(row);
  if (keep_record_) recorded_.push_back(std::move(row));
}

}  // namespace sluice
