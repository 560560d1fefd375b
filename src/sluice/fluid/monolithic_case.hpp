// What a model that joins the bodies' velocity-level step (the monolithic coupling scheme:
// granular, constraint) needs of its case: the complementarity contact method.
#pragma once

#include <string>

#include "sluice/io/case_config.hpp"

namespace sluice {

// Sets contact.method to complementarity; an InputError naming contact.method when the case
// asks for the penalty method (`why`: what meets in the one step).
void require_complementarity(io::CaseConfig& config, const std::string& model,
                             const std::string& why);

}  // namespace sluice
