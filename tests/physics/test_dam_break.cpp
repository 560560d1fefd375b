// F2 of VALIDATION.md: 2D dam break, surge front against Koshizuka & Oka (1996).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "physics_support.hpp"
#include "reported_figure.hpp"
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

testing::DamBreakFront testing::dam_break_front(const std::vector<std::string>& overrides) {
  const auto reference = reference_front();
  EXPECT_GE(reference.size(), 10u);
  Simulation<2> sim(testing::load_case("dam_break_2d.yaml", overrides));
  io::ProbeConfig front;
  front.kind = io::ProbeKind::kSurgeFront;
  Probes probe({front}, "");
  std::vector<double> times{0}, fronts{probe.measure(sim.fluid().observation())[0]};
  testing::run_until(sim, 0.72, [&](const StepClock& s) {
    times.push_back(s.time);
    fronts.push_back(probe.measure(sim.fluid().observation())[0]);
  });
  // The run's front at the experiment's time t read on a clock started `delay` later.
  auto rms_with_delay = [&](double delay) {
    double sum2 = 0;
    int count = 0;
    for (const auto& [t, x] : reference) {
      if (t > 0.70) continue;
      const double simulated = testing::interpolate(times, fronts, std::max(t - delay, 0.0));
      sum2 += (simulated - x) * (simulated - x);
      ++count;
    }
    return std::sqrt(sum2 / count);
  };
  DamBreakFront out{rms_with_delay(0), rms_with_delay(0), 0};
  for (int ms = 1; ms <= 80; ++ms) {
    const double rms = rms_with_delay(0.001 * ms);
    if (rms < out.delayed_rms) out = {out.rms, rms, 0.001 * ms};
  }
  return out;
}

namespace {

// Every model at the spacing its other CI checks use and at half of it, held to VALIDATION.md's
// two bars: (a) below 0.40 m as measured, (b) below 0.08 m with the experiment's clock delayed
// by the fitted d ('granular', a packing of spheres, to (a) only).
struct FrontRun {
  const char* model;
  double ci_spacing;
  bool halved;  // at half the CI spacing
  bool held_to_the_delayed_bar;
  double spacing() const { return halved ? ci_spacing / 2 : ci_spacing; }
};

class DamBreakFront : public ::testing::TestWithParam<FrontRun> {};

TEST_P(DamBreakFront, MeetsBothBars) {
  const FrontRun run = GetParam();
  const testing::DamBreakFront front = testing::dam_break_front(
      {std::string("model.name=") + run.model, "spacing=" + std::to_string(run.spacing())});
  std::printf(
      "F2 %s at %g m: front RMS (a) %.3f m as measured, (b) %.3f m with the experiment "
      "%.3f s later\n",
      run.model, run.spacing(), front.rms, front.delayed_rms, front.delay);
  const std::string at = fmt::format("F2 `{}` at {} m, front RMS", run.model, run.spacing());
  testing::expect_figure({at + " (a) as measured", "m", 3}, front.rms, testing::Bound::below, 0.40);
  if (run.held_to_the_delayed_bar) {
    testing::expect_figure({at + " (b) delayed", "m", 3}, front.delayed_rms, testing::Bound::below,
                           0.08);
  }
}

// The halved runs are the slow ones (mps at 0.0125 m: minutes): scripts/test_all.sh runs them
// in the release build only.
INSTANTIATE_TEST_SUITE_P(
    F2, DamBreakFront,
    ::testing::Values(
        FrontRun{"wcsph", 0.025, false, true}, FrontRun{"wcsph", 0.025, true, true},
        FrontRun{"mps", 0.025, false, true}, FrontRun{"mps", 0.025, true, true},
        FrontRun{"penalty-sph", 0.025, false, true}, FrontRun{"penalty-sph", 0.025, true, true},
        FrontRun{"constraint", 0.05, false, true}, FrontRun{"constraint", 0.05, true, true},
        FrontRun{"granular", 0.05, false, false}, FrontRun{"granular", 0.05, true, false},
        FrontRun{"mac", 0.05, false, true}, FrontRun{"mac", 0.05, true, true}),
    [](const ::testing::TestParamInfo<FrontRun>& info) {
      std::string name = info.param.model;
      for (char& c : name) {
        if (c == '-') c = '_';
      }
      return name + (info.param.halved ? "_at_half_the_ci_spacing" : "_at_the_ci_spacing");
    });

}  // namespace
}  // namespace sluice
