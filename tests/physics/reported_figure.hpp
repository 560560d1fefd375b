// A physics check's figure asserted against its bar and written, with the bar, into the test's
// report. ctest keeps one report per physics test (build/PRESET/tests/reports/), and
// validation/margins.py reads the release and baseline builds' reports into docs/validation.md's
// tables: the tables show what the tests measured and held, never a figure typed by hand.
#pragma once

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace sluice::testing {

// How a figure meets its bar: below it, above it, or within it on either side (|figure| < bar,
// for a deviation from a target).
enum class Bound { below, above, within };

struct Figure {
  std::string name;  // as the tables print it; unique within a test
  std::string unit;  // "%", "m", "Pa", or "" for a count or a ratio
  int decimals = 3;  // printed after the decimal point; negative: 3 significant digits
};

inline std::string format_figure(double value, int decimals) {
  return decimals < 0 ? fmt::format("{:.3g}", value) : fmt::format("{:.{}f}", value, decimals);
}

// The figure's distance to its bar, positive where the bar is met.
inline double margin_to_bar(double measured, Bound bound, double bar) {
  switch (bound) {
    case Bound::below:
      return bar - measured;
    case Bound::above:
      return measured - bar;
    case Bound::within:
      return bar - std::abs(measured);
  }
  return bar - measured;
}

inline const char* bound_name(Bound bound) {
  switch (bound) {
    case Bound::below:
      return "below";
    case Bound::above:
      return "above";
    case Bound::within:
      return "within";
  }
  return "below";
}

// Records the figure and its bar in the report as the property `figure.name` =
// "measured;bound;bar;unit;decimals;held" (numbers in full precision; held: "held" where the test
// asserts the bar, "limit" where the model is known not to meet it and the figure is reported).
inline void record_figure(const Figure& figure, double measured, Bound bound, double bar,
                          bool held) {
  ::testing::Test::RecordProperty(
      figure.name, fmt::format("{};{};{};{};{};{}", measured, bound_name(bound), bar, figure.unit,
                               figure.decimals, held ? "held" : "limit"));
}

// A bar the model does not meet, reported with its figure and not asserted.
inline void report_limit(const Figure& figure, double measured, Bound bound, double bar) {
  record_figure(figure, measured, bound, bar, false);
}

// Asserts the figure against its bar (a failure, not a stop) and records both in the report.
inline void expect_figure(const Figure& figure, double measured, Bound bound, double bar) {
  record_figure(figure, measured, bound, bar, true);
  EXPECT_TRUE(std::isfinite(measured) && margin_to_bar(measured, bound, bar) >= 0)
      << figure.name << ": " << format_figure(measured, figure.decimals) << " " << figure.unit
      << ", bar: " << bound_name(bound) << " " << format_figure(bar, figure.decimals) << " "
      << figure.unit;
}

}  // namespace sluice::testing
