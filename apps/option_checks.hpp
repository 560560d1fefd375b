// Checks of command-line values whose messages read like the case file's: the option, what is
// allowed, the value given ("--threads: must be a whole number of at least 1, got 0"). CLI11's
// own range checks print the limits of a double in 300 digits.
#pragma once

#include <CLI/CLI.hpp>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>

#include "sluice/sim/device_choice.hpp"

namespace sluice {

// A count of at least one: threads, jobs.
inline CLI::Validator at_least_one() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        errno = 0;
        const long value = std::strtol(text.c_str(), &end, 10);
        const bool whole = !text.empty() && *end == '\0' && errno == 0;
        if (whole && value >= 1 && value <= 1000000) return {};
        return "must be a whole number of at least 1, got " + text;
      },
      "INT >= 1");
}

// A time in seconds, finite and above zero: --end.
inline CLI::Validator positive_seconds() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        const bool number = !text.empty() && *end == '\0';
        if (number && std::isfinite(value) && value > 0) return {};
        return "must be a time in seconds greater than zero, got " + text;
      },
      "SECONDS > 0");
}

// Where a run's loops run: --device.
inline CLI::Validator device_name() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (is_device_name(text)) return {};
        return "expected cpu, gpu or emulated, got '" + text + "'";
      },
      "cpu|gpu|emulated");
}

}  // namespace sluice
