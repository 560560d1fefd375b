// Typed errors: the library throws, the command line turns them into a message and an exit code.
#pragma once

#include <stdexcept>
#include <string>

namespace sluice {

// A problem with what the user gave us (case file, command line, output directory).
// what() is the full one-line message: "FILE:LINE: key 'a.b': problem".
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, std::string key, const std::string& problem);
  explicit InputError(const std::string& message) : std::runtime_error(message) {}

  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& key() const { return key_; }

 private:
  std::string file_;
  int line_ = 0;
  std::string key_;
};

// The run produced non-finite values or lost particles out of the domain.
class DivergenceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The start of every divergence message: "the run diverged at step N, t = T s: " (the step and
// time where the problem was found; docs/output.md#when-a-run-stops-early).
std::string diverged_at(long step, double time);

// Exit codes of the command line, documented in README.md.
enum ExitCode : int { kExitOk = 0, kExitFailure = 1, kExitBadInput = 2, kExitDiverged = 3 };

}  // namespace sluice
