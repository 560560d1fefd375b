// sluice.Case and sluice.InputError (case_binding.cpp), and Python values as YAML.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace sluice::python {

// A Python value (None, bool, number, str, list, tuple, dict, numpy) as one line of YAML, as
// --set takes it: "[0.5, 1]", "{name: mps}". TypeError for anything else.
std::string yaml_text(const pybind11::handle& value);

// `set`'s {key path: value} as --set's "key.path=value" strings.
std::vector<std::string> set_overrides(const pybind11::dict& settings);

void bind_case(pybind11::module_& m);

}  // namespace sluice::python
