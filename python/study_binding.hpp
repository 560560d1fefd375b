// sluice.sweep and sluice.compare (study_binding.cpp).
#pragma once

#include <pybind11/pybind11.h>

namespace sluice::python {

void bind_studies(pybind11::module_& m);

}  // namespace sluice::python
