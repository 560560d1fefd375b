#include "sluice/core/errors.hpp"

#include <fmt/format.h>

namespace sluice {

namespace {
std::string format_input_error(const std::string& file, int line, const std::string& key,
                               const std::string& problem) {
  std::string where = file;
  if (line > 0) where += fmt::format(":{}", line);
  if (key.empty()) return fmt::format("{}: {}", where, problem);
  return fmt::format("{}: key '{}': {}", where, key, problem);
}
}  // namespace

InputError::InputError(std::string file, int line, std::string key, const std::string& problem)
    : std::runtime_error(format_input_error(file, line, key, problem)),
      file_(std::move(file)),
      line_(line),
      key_(std::move(key)) {}

std::string diverged_at(long step, double time) {
  return fmt::format("the run diverged at step {}, t = {:.6g} s: ", step, time);
}

}  // namespace sluice
