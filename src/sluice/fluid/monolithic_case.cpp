#include "sluice/fluid/monolithic_case.hpp"

#include <fmt/format.h>

#include "sluice/core/errors.hpp"

namespace sluice {

void require_complementarity(io::CaseConfig& config, const std::string& model,
                             const std::string& why) {
  if (config.contact.method && *config.contact.method != "complementarity") {
    throw InputError(
        config.file(), config.contact.line, "contact.method",
        fmt::format("the {} model needs contact.method: complementarity ({})", model, why));
  }
  config.contact.method = "complementarity";
}

}  // namespace sluice
