// sluice.Simulation and sluice.DivergenceError (simulation_binding.cpp).
#pragma once

#include <pybind11/pybind11.h>

namespace sluice {
class HypreSession;  // linear/hypre_session.hpp
}

namespace sluice::python {

// The process's MPI and hypre, started when first asked for (with the GIL held), stopped when
// Python exits.
HypreSession& hypre_session();

void bind_simulation(pybind11::module_& m);

}  // namespace sluice::python
