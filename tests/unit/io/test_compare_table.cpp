// Reading back a run's CSV files (io/csv_table.hpp) and the table of `sluice compare`
// (io/compare_table.hpp): what each model's row says, from files written here by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

#include "sluice/io/compare_table.hpp"
#include "sluice/io/csv_table.hpp"
#include "support/scratch_dir.hpp"

namespace sluice::io {
namespace {

void write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

TEST(CsvTable, ReadsColumnsByName) {
  const test_support::ScratchDir dir("csv_table");
  write(dir / "a.csv", "time,x [m]\n0,1.5\n0.1,-2e-3\n\n0.2,inf\n");
  const CsvTable table = read_csv_table((dir / "a.csv").string());
  EXPECT_EQ(table.columns, (std::vector<std::string>{"time", "x [m]"}));
  ASSERT_TRUE(table.column("x [m]"));
  EXPECT_EQ(table.values(*table.column("x [m]")),
            (std::vector<double>{1.5, -2e-3, std::numeric_limits<double>::infinity()}));
  EXPECT_FALSE(table.column("y"));
}

TEST(CsvTable, NamesTheLineOfABadRow) {
  const test_support::ScratchDir dir("csv_table");
  write(dir / "short.csv", "time,x\n0,1\n0.1\n");
  write(dir / "word.csv", "time,x\n0,abc\n");
  const auto message = [&](const std::string& name) {
    try {
      read_csv_table((dir / name).string());
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(message("short.csv"), (dir / "short.csv").string() + ":3: 1 values for 2 columns");
  EXPECT_EQ(message("word.csv"),
            (dir / "word.csv").string() + ":2: 'abc' is not a number (column x)");
  EXPECT_EQ(message("none.csv"), (dir / "none.csv").string() + ": cannot open the file");
}

// A run with bodies and three probes: the loads are averaged over the rows after t = 0, their
// peak is the largest mean over 0.05 s (the spike of 9 is not it), the water height's rise
// counts from its start.
TEST(CompareTable, FiguresOfARunAndOneRowPerModel) {
  const test_support::ScratchDir dir("compare_table");
  write(dir / "stats.json",
        "{\"element_name\": \"cells\", \"particles\": 900, \"fluid_particles\": 600, "
        "\"steps\": 40, \"wall_seconds\": 2.5, \"wall_seconds_per_simulated_second\": 12.5, "
        "\"bodies\": 2}\n");
  write(dir / "loads.csv",
        "time,a_drag,a_lift,a_side,all_bodies_drag,all_bodies_lift,all_bodies_side\n"
        "0,0,0,0,100,100,0\n0.01,0,0,0,1,10,0\n0.02,0,0,0,2,10,0\n0.03,0,0,0,9,10,0\n"
        "0.04,0,0,0,2,10,0\n0.05,0,0,0,1,40,0\n");
  write(dir / "probes.csv",
        "time [s],gauge [m],front [m],p [Pa]\n0,0.2,1,50\n0.1,0.25,1.5,80\n"
        "0.2,0.22,1.8,60\n");
  std::vector<ProbeConfig> probes(3);
  probes[0] = {"gauge", ProbeKind::kWaterHeight};
  probes[1] = {"front", ProbeKind::kSurgeFront};
  probes[2] = {"p", ProbeKind::kPressure};
  CompareResult mac{"mac", "model={name: mac, cell_size: 0.04}", "done", "", {}};
  read_compare_figures(dir.path().string(), probes, 3, mac);
  EXPECT_EQ(mac.elements, "600 cells");
  const Measurements expected{
      {"steps", 40},         {"wall [s]", 2.5},        {"wall per simulated s", 12.5},
      {"mean drag [N]", 3},  {"peak drag [N]", 4},     {"mean lift [N]", 16},
      {"peak lift [N]", 20}, {"gauge rise [m]", 0.05}, {"front end [m]", 1.8},
      {"p peak [Pa]", 80}};
  ASSERT_EQ(mac.measurements.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) {
    EXPECT_EQ(mac.measurements[k].first, expected[k].first);
    EXPECT_NEAR(mac.measurements[k].second, expected[k].second, 1e-12) << expected[k].first;
  }
  const CompareResult failed{"mps", "defaults", "diverged", "", {}};
  const std::string csv = compare_table_csv({mac, failed});
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "model,status,settings,fluid,steps,wall [s],wall per simulated s,mean drag [N],"
            "peak drag [N],mean lift [N],peak lift [N],gauge rise [m],front end [m],p peak [Pa]");
  EXPECT_NE(csv.find("\nmac,done,\"model={name: mac, cell_size: 0.04}\",600 "
                     "cells,40,2.5,12.5,3,4,16,20,0.05,1.8,"
                     "80\n"),
            std::string::npos)
      << csv;
  EXPECT_NE(csv.find("\nmps,diverged,defaults,,,,,,,,,,,\n"), std::string::npos) << csv;
  const std::string markdown = compare_table_markdown({mac, failed});
  EXPECT_EQ(std::count(markdown.begin(), markdown.end(), '\n'), 4);  // header, rule, two rows
}

}  // namespace
}  // namespace sluice::io
