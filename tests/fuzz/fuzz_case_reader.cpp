// libFuzzer harness for the case-file reader: the input is a case's YAML text, then, after each
// NUL byte, one --set string. Bad input must end in InputError, the one exception the reader
// promises; any other exception, a crash or a sanitizer report is a bug.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "sluice/core/errors.hpp"
#include "sluice/io/case_config.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = input.find('\0', start);
    parts.push_back(input.substr(start, end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  const std::vector<std::string> overrides(parts.begin() + 1, parts.end());
  try {
    sluice::io::parse_case(parts.front(), "fuzz.yaml", overrides);
  } catch (const sluice::InputError&) {
  }
  return 0;
}
