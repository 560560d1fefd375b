// Shared set-up for the physics checks: load a shipped case, run it in-process.
#pragma once

#include <string>
#include <vector>

#include "sluice/io/case_config.hpp"
#include "sluice/sim/simulation.hpp"

namespace sluice::testing {

inline io::CaseConfig load_case(const std::string& name,
                                const std::vector<std::string>& overrides = {}) {
  return io::read_case(std::string(SLUICE_SOURCE_DIR) + "/cases/" + name, overrides);
}

// Runs until `end`, calling observe(clock) after every step.
template <int D, class Observe>
void run_until(Simulation<D>& sim, double end, Observe&& observe) {
  while (sim.time() < end * (1 - 1e-12)) {
    sim.step(end);
    observe(sim.clock());
  }
}

// F2: the RMS difference [m] between the 2D dam break's surge front (cases/dam_break_2d.yaml
// with `overrides`) and Koshizuka & Oka's (1996) over t in [0, 0.70] s.
double dam_break_front_rms(const std::vector<std::string>& overrides);

}  // namespace sluice::testing
