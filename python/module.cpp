// The compiled part of the `sluice` Python package (python/sluice/__init__.py): thin bindings
// of the library's case, run and outputs; the package adds nothing the library does not do.
#include <pybind11/pybind11.h>

#include "case_binding.hpp"
#include "simulation_binding.hpp"
#include "sluice/core/build_info.hpp"
#include "study_binding.hpp"

PYBIND11_MODULE(_sluice, m) {
  m.doc() =
      "sluice's engine: cases, simulations stepped from Python, their fields and loads; sweeps "
      "and comparisons of models.";
  m.attr("__version__") = std::string(sluice::sluice_version());
  m.attr("source_revision") = std::string(sluice::source_revision());
  sluice::python::bind_case(m);
  sluice::python::bind_simulation(m);
  sluice::python::bind_studies(m);
}
