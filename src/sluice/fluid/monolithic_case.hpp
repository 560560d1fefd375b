// What a model that joins the bodies' velocity-level step (the monolithic coupling scheme:
// granular, constraint) needs of its case: the complementarity contact method.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "sluice/coupling/body_motion.hpp"
#include "sluice/io/case_config.hpp"

namespace sluice {

// Sets contact.method to complementarity; an InputError naming contact.method when the case
// asks for the penalty method (`why`: what meets in the one step).
void require_complementarity(io::CaseConfig& config, const std::string& model,
                             const std::string& why);

// The loads a monolithic fluid's last solve put on the first `bodies` bodies (zero for those
// it did not reach), for the output.
inline std::vector<Wrench> loads_of_solve(const std::vector<Wrench>& solved, std::size_t bodies) {
  std::vector<Wrench> out(bodies);
  for (std::size_t b = 0; b < std::min(bodies, solved.size()); ++b) out[b] = solved[b];
  return out;
}

}  // namespace sluice
