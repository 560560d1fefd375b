// The plan and the summary table of `sluice sweep` (io/sweep_plan.hpp, io/sweep_table.hpp).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "sluice/core/errors.hpp"
#include "sluice/io/sweep_plan.hpp"
#include "sluice/io/sweep_table.hpp"

namespace sluice::io {
namespace {

TEST(SweepPlan, SplitsValuesAtCommasOutsideBracketsAndQuotes) {
  const SweepSetting ks = parse_sweep_setting("model.Ks=5e3, 5e4,1e5");
  EXPECT_EQ(ks.key, "model.Ks");
  EXPECT_EQ(ks.values, (std::vector<std::string>{"5e3", "5e4", "1e5"}));
  const SweepSetting box = parse_sweep_setting("fluid.blocks.0.max=[0.5, 1],[0.6, 1]");
  EXPECT_EQ(box.values, (std::vector<std::string>{"[0.5, 1]", "[0.6, 1]"}));
  EXPECT_EQ(parse_sweep_setting("spacing=0.05").values.size(), 1u);
  // A quoted YAML string keeps its commas (and brackets).
  const SweepSetting names = parse_sweep_setting(R"(name="a, b",'c,[d',e)");
  EXPECT_EQ(names.values, (std::vector<std::string>{R"("a, b")", "'c,[d'", "e"}));
}

TEST(SweepPlan, RejectsAMissingKeyOrAnEmptyValue) {
  EXPECT_THROW(parse_sweep_setting("=1,2"), InputError);
  EXPECT_THROW(parse_sweep_setting("spacing"), InputError);
  try {
    parse_sweep_setting("model.Ks=5e3,,1e5");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "--set model.Ks: key 'model.Ks': empty value in the list '5e3,,1e5'");
  }
}

TEST(SweepPlan, EveryCombinationLastAxisFastest) {
  const std::vector<SweepSetting> settings{parse_sweep_setting("a=1,2"),
                                           parse_sweep_setting("end_time=0.1"),
                                           parse_sweep_setting("b=x,y,z")};
  EXPECT_EQ(sweep_axes(settings), (std::vector<std::string>{"a", "b"}));
  const std::vector<SweepRun> runs = sweep_runs(settings);
  ASSERT_EQ(runs.size(), 6u);
  EXPECT_EQ(runs[0].overrides, (std::vector<std::string>{"a=1", "end_time=0.1", "b=x"}));
  EXPECT_EQ(runs[0].values, (std::vector<std::string>{"1", "x"}));
  EXPECT_EQ(runs[1].values, (std::vector<std::string>{"1", "y"}));
  EXPECT_EQ(runs[5].values, (std::vector<std::string>{"2", "z"}));
}

// Keys joined by '+' are one axis: each value goes to every key.
TEST(SweepPlan, JoinedKeysTakeEachValueTogether) {
  const std::vector<SweepSetting> settings{
      parse_sweep_setting("fluid.blocks.0.max.2+boundaries.0.depth=0.12,0.2"),
      parse_sweep_setting("u=1,2")};
  EXPECT_EQ(sweep_axes(settings),
            (std::vector<std::string>{"fluid.blocks.0.max.2+boundaries.0.depth", "u"}));
  const std::vector<SweepRun> runs = sweep_runs(settings);
  ASSERT_EQ(runs.size(), 4u);
  EXPECT_EQ(runs[2].overrides, (std::vector<std::string>{"fluid.blocks.0.max.2=0.2",
                                                         "boundaries.0.depth=0.2", "u=1"}));
  EXPECT_EQ(runs[2].values, (std::vector<std::string>{"0.2", "1"}));
  try {
    parse_sweep_setting("a++b=1,2");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "--set a++b: key 'a++b': an empty key path among those joined by '+'");
  }
}

TEST(SweepTable, OneRowPerRunMeasurementsInOrderOfFirstAppearance) {
  const std::vector<SweepResult> results{
      {{"5e3"}, "done", {{"held_back_fraction", 0.25}, {"steps", 10}}},
      {{"5e4"}, "diverged", {}},
      {{"1e5"}, "done", {{"held_back_fraction", 1}, {"front [m]", 1.5}, {"steps", 12}}}};
  EXPECT_EQ(sweep_table_csv({"model.Ks"}, results),
            "run,model.Ks,status,held_back_fraction,steps,front [m]\n"
            "1,5e3,done,0.25,10,\n"
            "2,5e4,diverged,,,\n"
            "3,1e5,done,1,12,1.5\n");
  EXPECT_EQ(sweep_table_markdown({"model.Ks"}, {results[0]}),
            "| run | model.Ks | status | held_back_fraction | steps |\n"
            "|---|---|---|---|---|\n"
            "| 1 | 5e3 | done | 0.25 | 10 |\n");
  // A value with a comma is quoted in the CSV.
  EXPECT_EQ(sweep_table_csv({"box"}, {{{"[0.5, 1]"}, "done", {}}}),
            "run,box,status\n1,\"[0.5, 1]\",done\n");
}

TEST(SweepTable, ReadsTheMeasurementsOfARunsStatistics) {
  const std::string path = ::testing::TempDir() + "/sweep_stats.json";
  std::ofstream(path) << "{\n  \"particles\": 100,\n  \"steps\": 42,\n  \"wall_seconds\": 1.5,\n"
                         "  \"fluid_counters\": {\"pressure_solves\": 42},\n"
                         "  \"final_probes\": {\"front [m]\": 2.25, \"P1 [Pa]\": 900},\n"
                         "  \"stage_seconds\": {\"solve\": 0.5}\n}\n";
  const Measurements m = read_run_measurements(path);
  ASSERT_EQ(m.size(), 5u);
  EXPECT_EQ(m[0], (std::pair<std::string, double>{"pressure_solves", 42}));
  EXPECT_EQ(m[1], (std::pair<std::string, double>{"front [m]", 2.25}));
  EXPECT_EQ(m[2], (std::pair<std::string, double>{"P1 [Pa]", 900}));
  EXPECT_EQ(m[3], (std::pair<std::string, double>{"steps", 42}));
  EXPECT_EQ(m[4], (std::pair<std::string, double>{"wall_seconds", 1.5}));
  std::remove(path.c_str());
  EXPECT_THROW(read_run_measurements(path), std::runtime_error);
}

}  // namespace
}  // namespace sluice::io
