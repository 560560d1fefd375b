// sluice.sweep and sluice.compare: the command line's studies (study/sweep.hpp,
// study/compare.hpp), their tables given back as rows of dicts. Each run is a child `sluice run`:
// the executable built beside this module, or $SLUICE_EXECUTABLE.
#include "study_binding.hpp"

#include <fmt/format.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
#include <yaml-cpp/yaml.h>

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "case_binding.hpp"
#include "simulation_binding.hpp"
#include "sluice/core/errors.hpp"
#include "sluice/study/compare.hpp"
#include "sluice/study/sweep.hpp"

namespace py = pybind11;

namespace sluice::python {

namespace {

std::string sluice_executable() {
  const char* chosen = std::getenv("SLUICE_EXECUTABLE");
  return chosen != nullptr && *chosen != '\0' ? chosen : SLUICE_EXECUTABLE_PATH;
}

// A swept value as Python reads it best: a number where it is one, else its YAML text.
py::object value_of(const std::string& text) {
  char* end = nullptr;
  const double number = std::strtod(text.c_str(), &end);
  if (!text.empty() && end == text.c_str() + text.size()) return py::float_(number);
  return py::str(text);
}

void add_measurements(py::dict& row, const io::Measurements& measurements) {
  for (const auto& [name, value] : measurements) row[py::str(name)] = value;
}

// One value of an axis as YAML text; a string with a comma, a bracket or a quote in double
// quotes, so that the axis's list splits between its values alone.
std::string axis_value_text(const py::handle& value) {
  if (!py::isinstance<py::str>(value)) return yaml_text(value);
  const std::string text = value.cast<std::string>();
  if (text.find_first_of(",[]{}\"'") == std::string::npos) return yaml_text(value);
  YAML::Emitter quoted;
  quoted << YAML::DoubleQuoted << text;
  return quoted.c_str();
}

// `set`'s {key: value or [values]} as the command line's --set KEY=V1,V2: a list or tuple is an
// axis of the sweep (a list value is given inside one: [[0.5, 1], [0.6, 1]]), anything else is
// set in every run.
std::vector<std::string> sweep_settings(const py::dict& settings) {
  std::vector<std::string> out;
  for (const auto& [key, value] : settings) {
    std::string values;
    if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
      if (py::len(value) == 0) {
        const std::string name = py::str(key).cast<std::string>();
        throw InputError("--set " + name, 0, name, "an empty list of values");
      }
      for (const auto& item : value) {
        if (!values.empty()) values += ',';
        values += axis_value_text(item);
      }
    } else {
      values = yaml_text(value);
    }
    out.push_back(fmt::format("{}={}", py::str(key).cast<std::string>(), values));
  }
  return out;
}

// The options both studies take from Python, their runs started by this module's sluice.
StudyOptions study_options(const std::filesystem::path& case_path,
                           std::vector<std::string> settings,
                           const std::optional<std::filesystem::path>& out, int jobs,
                           std::optional<double> end, bool progress) {
  if (jobs < 0) throw py::value_error("jobs must be 0 (the default) or more");
  if (end && !(*end > 0)) throw py::value_error("end must be above 0 s");
  StudyOptions o;
  o.case_path = case_path;
  o.settings = std::move(settings);
  o.out_dir = out ? out->string() : "";
  o.jobs = jobs;
  o.end_time = end.value_or(0);
  o.program = sluice_executable();
  o.hypre = &hypre_session();
  o.report = progress;
  return o;
}

// A study run with the GIL until its checks have passed (they may solve with hypre, which a
// simulation stepping in another Python thread shares), then without it, other threads going
// on, until it ends; Ctrl-C stops its runs (KeyboardInterrupt).
template <class Outcome, class Options>
Outcome run_study(Outcome (*study)(const Options&), Options options) {
  struct ReleasedAfterChecks {
    PyThreadState* saved = nullptr;
    ~ReleasedAfterChecks() {
      if (saved != nullptr) PyEval_RestoreThread(saved);
    }
  } gil;
  options.checked = [&gil] { gil.saved = PyEval_SaveThread(); };
  options.stop_requested = [] {
    const py::gil_scoped_acquire python;
    return PyErr_CheckSignals() != 0;  // leaves the KeyboardInterrupt set
  };
  try {
    return study(options);
  } catch (const StudyStopped&) {
    if (gil.saved != nullptr) PyEval_RestoreThread(std::exchange(gil.saved, nullptr));
    throw py::error_already_set();
  }
}

py::list sweep(const std::filesystem::path& case_path, const py::dict& settings,
               const std::optional<std::filesystem::path>& out, int jobs, std::optional<double> end,
               bool progress) {
  SweepOptions o;
  static_cast<StudyOptions&>(o) =
      study_options(case_path, sweep_settings(settings), out, jobs, end, progress);
  const SweepOutcome outcome = run_study(&run_sweep, o);
  py::list rows;
  for (std::size_t k = 0; k < outcome.results.size(); ++k) {
    const io::SweepResult& r = outcome.results[k];
    py::dict row;
    row["run"] = k + 1;
    for (std::size_t a = 0; a < outcome.keys.size(); ++a) {
      row[py::str(outcome.keys[a])] = value_of(r.values[a]);
    }
    row["status"] = r.status;
    row["out"] = fmt::format("{}/run_{:03d}", outcome.out_dir, k + 1);
    add_measurements(row, r.measurements);
    rows.append(row);
  }
  return rows;
}

py::list compare(const std::filesystem::path& case_path, const std::vector<std::string>& models,
                 const py::dict& settings, const std::optional<std::filesystem::path>& out,
                 int jobs, std::optional<double> end, bool progress) {
  CompareOptions o;
  static_cast<StudyOptions&>(o) =
      study_options(case_path, set_overrides(settings), out, jobs, end, progress);
  o.models = models;
  o.models_option = "models";
  const CompareOutcome outcome = run_study(&run_compare, o);
  py::list rows;
  for (const io::CompareResult& r : outcome.results) {
    py::dict row;
    row["model"] = r.model;
    row["status"] = r.status;
    row["settings"] = r.settings;
    row["fluid"] = r.elements;
    row["out"] = outcome.out_dir + "/" + r.model;
    add_measurements(row, r.measurements);
    rows.append(row);
  }
  return rows;
}

}  // namespace

void bind_studies(py::module_& m) {
  m.def("sweep", &sweep, py::arg("case"), py::arg("set"), py::arg("out") = py::none(),
        py::arg("jobs") = 0, py::arg("end") = py::none(), py::arg("progress") = true, R"doc(
Runs the case file `case` for every combination of the values in `set`, as `sluice sweep` does,
and gives back its table (OUT/summary.csv) as a list of rows, one dict per run:

    rows = sluice.sweep("cases/floating_box_2d.yaml",
                        set={"bodies.0.density": [400, 600, 800], "end_time": 1.0})
    [(r["bodies.0.density"], r["status"], r["steps"]) for r in rows]

A list or tuple in `set` is an axis (a list-valued key's values go inside one: [[0.5, 1],
[0.6, 1]]); any other value applies to every run. A row holds 'run' (1, 2, ...), each swept key
(a number where the value is one), 'status' ('done', 'diverged', 'failed (exit N)'), 'out' (the
run's folder) and the run's measurements by name (its counters, each probe at the end, 'steps',
'wall_seconds'). Every combination is checked before any runs (bad input: sluice.InputError);
a run that diverges or fails is a row with its status. `jobs` runs at once (0: one per core),
`end` overrides every run's end time, `progress` prints the command line's lines (the start,
each run's end, the table). Ctrl-C stops the runs (KeyboardInterrupt). Each run is a
child `sluice run` (the executable built with this module, or $SLUICE_EXECUTABLE).)doc");
  m.def("compare", &compare, py::arg("case"), py::arg("models") = std::vector<std::string>{},
        py::arg("set") = py::dict(), py::arg("out") = py::none(), py::arg("jobs") = 1,
        py::arg("end") = py::none(), py::arg("progress") = true, R"doc(
Runs the case file `case` with each fluid model in `models` (default: the case's compare:
entries, or every model), as `sluice compare` does, and gives back its table
(OUT/compare.csv) as a list of rows, one dict per model:

    rows = sluice.compare("cases/dam_break_2d.yaml", models=["wcsph", "mps"], end=0.2)

A row holds 'model', 'status', 'settings' (the compare: settings of its run), 'fluid' (its
particles or cells), 'out' (the run's folder) and what it measured by name: steps, wall
seconds, the bodies' mean and peak drag and lift, each probe's rise, end or peak. `set` applies
to every run, after the model's own settings. Every model's case is checked before any runs
(bad input, an unknown model too: sluice.InputError). `jobs` runs at once (default 1, so that
the wall times compare).)doc");
}

}  // namespace sluice::python
