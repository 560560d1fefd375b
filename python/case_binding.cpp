// sluice.Case and sluice.InputError: a case read and validated as `sluice check` reads it, from a
// file (with --set's overrides) or from a Python dict.
#include "case_binding.hpp"

#include <fmt/format.h>
#include <pybind11/stl.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <string>
#include <vector>

#include "sluice/core/errors.hpp"
#include "sluice/io/case_config.hpp"

namespace py = pybind11;

namespace sluice::python {

namespace {

// A Python value (None, bool, int, float, str, list, tuple, dict) as YAML.
YAML::Node yaml_of(const py::handle& value) {
  if (value.is_none()) return YAML::Node(YAML::NodeType::Null);
  // bool before int: Python's bool is an int.
  if (py::isinstance<py::bool_>(value)) return YAML::Node(value.cast<bool>());
  if (py::isinstance<py::int_>(value)) return YAML::Node(value.cast<long long>());
  // The shortest text that reads back as the same double (0.05, not 0.050000000000000003);
  // YAML's own for infinities and NaN.
  if (py::isinstance<py::float_>(value)) {
    const double number = value.cast<double>();
    return std::isfinite(number) ? YAML::Node(fmt::format("{}", number)) : YAML::Node(number);
  }
  if (py::isinstance<py::str>(value)) return YAML::Node(value.cast<std::string>());
  if (py::isinstance<py::dict>(value)) {
    YAML::Node map(YAML::NodeType::Map);
    for (const auto& [key, item] : value.cast<py::dict>()) {
      map[py::str(key).cast<std::string>()] = yaml_of(item);
    }
    return map;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    YAML::Node list(YAML::NodeType::Sequence);
    for (const auto& item : value) list.push_back(yaml_of(item));
    return list;
  }
  // numpy's scalars and arrays, and anything else that turns into one of the above.
  if (py::hasattr(value, "tolist")) return yaml_of(value.attr("tolist")());
  throw py::type_error("a case holds None, bools, numbers, strings, lists and dicts, not " +
                       py::str(py::type::of(value)).cast<std::string>());
}

std::string flow_text(const YAML::Node& node) {
  YAML::Emitter out;
  out << YAML::Flow << node;
  return out.c_str();
}

}  // namespace

std::string yaml_text(const py::handle& value) {
  return flow_text(yaml_of(value));
}

std::vector<std::string> set_overrides(const py::dict& settings) {
  std::vector<std::string> overrides;
  for (const auto& [key, value] : settings) {
    overrides.push_back(py::str(key).cast<std::string>() + "=" + yaml_text(value));
  }
  return overrides;
}

void bind_case(py::module_& m) {
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  input_error.attr("__doc__") =
      "Bad input: a case, a --set override or a checkpoint that sluice cannot use. Its message "
      "names the file, line and key, as the command line's does; the attributes `file`, `line` "
      "and `key` hold them (line 0 and key '' where there is none).";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      const py::object type = input_error;
      py::object error = type(e.what());
      error.attr("file") = e.file();
      error.attr("line") = e.line();
      error.attr("key") = e.key();
      PyErr_SetObject(input_error.ptr(), error.ptr());
    }
  });

  py::class_<io::CaseConfig>(m, "Case", R"doc(
A case, read and checked as `sluice check` checks it (docs/case-format.md).

    sluice.Case.from_yaml("cases/dam_break_2d.yaml", set={"model.name": "mps"})
    sluice.Case({"dimension": 2, "spacing": 0.02, ...})

Bad input raises sluice.InputError naming the file, line and key.)doc")
      .def(py::init([](const py::dict& mapping) {
             return io::parse_case(flow_text(yaml_of(mapping)), "<dict>");
           }),
           py::arg("mapping"),
           "A case from a dict laid out as a case file; messages name the file '<dict>'.")
      .def_static(
          "from_yaml",
          [](const std::string& path, const py::dict& settings) {
            return io::read_case(path, set_overrides(settings));
          },
          py::arg("path"), py::arg("set") = py::dict(),
          "Reads the case file at `path`; `set` maps key paths to values, as --set does: "
          "{'model.name': 'mps', 'end_time': 0.5}.")
      .def_property_readonly("name", [](const io::CaseConfig& c) { return c.name; })
      .def_property_readonly("dimension", [](const io::CaseConfig& c) { return c.dimension; })
      .def_property_readonly("end_time", [](const io::CaseConfig& c) { return c.end_time; })
      .def_property_readonly("spacing", [](const io::CaseConfig& c) { return c.spacing; })
      .def_property_readonly(
          "model", [](const io::CaseConfig& c) { return c.has_fluid() ? c.model_name : ""; },
          "The fluid model's name ('' for bodies alone).")
      .def_property_readonly("file", [](const io::CaseConfig& c) { return c.file(); })
      .def("__repr__", [](const io::CaseConfig& c) {
        return "<sluice.Case '" + c.name + "' (" + std::to_string(c.dimension) + "D, " +
               (c.has_fluid() ? c.model_name : std::string("bodies alone")) + ")>";
      });
}

}  // namespace sluice::python
