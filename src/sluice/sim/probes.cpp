#include "sluice/sim/probes.hpp"

namespace sluice {

Probes::Probes(const std::vector<io::ProbeConfig>& probes, const std::string& csv_path)
    : probes_(probes) {
  if (probes_.empty() || csv_path.empty()) return;
  std::vector<std::string> header{"time [s]"};
  for (const auto& p : probes_) {
    switch (p.kind) {
      case io::ProbeKind::kPressure:
        header.push_back(p.name + " [Pa]");
        break;
      case io::ProbeKind::kWaterHeight:
        header.push_back(p.name + " [m]");
        break;
      case io::ProbeKind::kSurgeFront:
        header.push_back(p.name + " [m]");
        break;
    }
  }
  csv_ = std::make_unique<io::CsvWriter>(csv_path, header);
}

std::vector<double> Probes::measure(const FluidSystem& fluid) const {
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
    }
  }
  return row;
}

void Probes::record(double time, const FluidSystem& fluid) {
  if (!csv_) return;
  std::vector<double> row{time};
  for (double v : measure(fluid)) row.push_back(v);
  csv_->row(row);
}

}  // namespace sluice
