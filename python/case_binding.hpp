// sluice.Case and sluice.InputError (case_binding.cpp).
#pragma once

#include <pybind11/pybind11.h>

namespace sluice::python {

void bind_case(pybind11::module_& m);

}  // namespace sluice::python
