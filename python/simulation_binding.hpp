// sluice.Simulation and sluice.DivergenceError (simulation_binding.cpp).
#pragma once

#include <pybind11/pybind11.h>

namespace sluice::python {

void bind_simulation(pybind11::module_& m);

}  // namespace sluice::python
