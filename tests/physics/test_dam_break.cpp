// F2 of VALIDATION.md: 2D dam break, surge front against Koshizuka & Oka (1996).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "physics_support.hpp"
#include "sluice/sim/probes.hpp"

namespace sluice {
namespace {

std::vector<std::pair<double, double>> reference_front() {
  std::ifstream in(std::string(SLUICE_SOURCE_DIR) +
                   "/validation/data/dam_break_front_koshizuka_oka_1996.tsv");
  std::vector<std::pair<double, double>> out;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    double t = 0, x = 0;
    if (fields >> t >> x) out.emplace_back(t, x);
  }
  return out;
}

}  // namespace

double testing::dam_break_front_rms(const std::vector<std::string>& overrides) {
  const auto reference = reference_front();
  EXPECT_GE(reference.size(), 10u);
  Simulation<2> sim(testing::load_case("dam_break_2d.yaml", overrides));
  io::ProbeConfig front;
  front.kind = io::ProbeKind::kSurgeFront;
  Probes probe({front}, "");
  std::vector<double> times{0}, fronts{probe.measure(sim.fluid())[0]};
  testing::run_until(sim, 0.72, [&](const StepClock& s) {
    times.push_back(s.time);
    fronts.push_back(probe.measure(sim.fluid())[0]);
  });
  double sum2 = 0;
  int count = 0;
  for (const auto& [t, x] : reference) {
    if (t > 0.70) continue;
    const auto k =
        static_cast<std::size_t>(std::lower_bound(times.begin(), times.end(), t) - times.begin());
    const double w = (t - times[k - 1]) / (times[k] - times[k - 1]);
    const double simulated = fronts[k - 1] + w * (fronts[k] - fronts[k - 1]);
    sum2 += (simulated - x) * (simulated - x);
    ++count;
  }
  return std::sqrt(sum2 / count);
}

namespace {

TEST(DamBreak2D, SurgeFrontMatchesExperiment) {
  const double rms = testing::dam_break_front_rms({});
  RecordProperty("front_rms_m", std::to_string(rms));
  std::printf("F2 surge-front RMS error: %.3f m\n", rms);
  EXPECT_LT(rms, 0.30);
}

}  // namespace
}  // namespace sluice
