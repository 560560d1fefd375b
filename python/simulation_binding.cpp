// sluice.Simulation: a case's run (sim/case_run.hpp) that a script steps, reads and stops, with
// its outputs written as the command line writes them.
#include "simulation_binding.hpp"

#include <omp.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <yaml-cpp/yaml.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "field_arrays.hpp"
#include "sluice/core/errors.hpp"
#include "sluice/coupling/coupler.hpp"
#include "sluice/exec/policy.hpp"
#include "sluice/fluid/fluid_observation.hpp"
#include "sluice/linear/hypre_session.hpp"
#include "sluice/sim/case_run.hpp"
#include "sluice/sim/device_choice.hpp"
#include "sluice/sim/rigid_bodies.hpp"

namespace py = pybind11;

namespace sluice::python {

HypreSession& hypre_session() {
  static HypreSession* session = [] {
    auto* s = new HypreSession;  // left to the exit handler, not to static destruction
    py::module_::import("atexit").attr("register")(py::cpp_function([s] { s->finish(); }));
    return s;
  }();
  return *session;
}

namespace {

// The case with its model on `device`, as --device puts it there; "cpu" for a model that runs
// only there leaves the case as it is.
io::CaseConfig on_device(const io::CaseConfig& config, const std::string& device) {
  check_device(config, device, "device");
  if (!sets_model_device(config, device)) return config;
  io::CaseConfig moved = config;
  moved.model = YAML::Clone(config.model);  // a YAML node is shared by its copies
  moved.model["device"] = device;
  return moved;
}

// OpenMP's thread count is the calling thread's: each simulation sets its own while it steps.
class ThreadCount {
 public:
  explicit ThreadCount(int threads) : before_(exec::thread_count()) {
    exec::set_thread_count(threads);
  }
  ~ThreadCount() { exec::set_thread_count(before_); }
  ThreadCount(const ThreadCount&) = delete;
  ThreadCount& operator=(const ThreadCount&) = delete;

 private:
  int before_;
};

class Simulation {
 public:
  Simulation(const io::CaseConfig& config, std::optional<std::string> out, int threads,
             std::optional<double> end, bool resume, bool progress,
             const std::optional<std::string>& device = std::nullopt)
      : threads_(threads > 0 ? threads : omp_get_max_threads()) {
    RunOptions options;
    options.out_dir = out.value_or("out/" + config.name);
    options.end_time = end;
    options.resume = resume;
    options.quiet = !progress;
    options.hypre = &hypre_session();
    options.keep_probe_record = true;
    const ThreadCount count(threads_);
    run_ = std::make_unique<CaseRun>(device ? on_device(config, *device) : config, options);
  }

  double time() const { return run_->time(); }
  long steps() const { return run_->step_count(); }
  int threads() const { return threads_; }
  // The run, for reading between steps (not while another thread steps it).
  const CaseRun& run() const {
    idle();
    return *run_;
  }

  // One step, not past `until` (the end, by default).
  void step(py::object self, std::optional<double> until) {
    usable();
    if (run_->finished()) throw py::value_error("the run is at its end time");
    const double limit = until.value_or(run_->end_time());
    check_until(limit);
    one_step(self, limit);
  }

  // Body `name`'s velocity from `controller(sim)` before every step (None: no longer).
  void drive(const std::string& name, const py::object& controller) {
    not_within_a_step();
    const std::size_t b = body_index(name);
    std::erase_if(controllers_, [&](const auto& c) { return c.first == b; });
    if (controller.is_none()) return;
    if (run_->config().bodies[b].motion != io::BodyMotion::kPrescribed) {
      throw py::value_error("body '" + name +
                            "' is not prescribed: only a body whose motion is prescribed can "
                            "be driven (motion: prescribed in the case)");
    }
    controllers_.emplace_back(b, controller);
  }
  double controller_seconds() const { return controller_seconds_; }

  // Steps to `until`, calling `callback(self)` every `every` simulated seconds (at each multiple
  // of it, which the steps land on) and checking between steps for Ctrl-C.
  void run_to(py::object self, std::optional<double> until, std::optional<double> every,
              const py::object& callback) {
    usable();
    const double limit = until.value_or(run_->end_time());
    if (limit > time()) check_until(limit);
    if (every && !(*every > 0)) throw py::value_error("every must be above 0 s");
    if (every && callback.is_none()) throw py::value_error("every needs a callback");
    const double tolerance = 1e-12 * std::max(1.0, limit);
    double next_call = every ? next_multiple(time(), *every) : limit;
    while (time() < limit - tolerance) {
      one_step(self, std::min(limit, next_call));
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (every && time() >= next_call - tolerance) {
        callback(self);
        next_call = next_multiple(time(), *every);
      }
    }
    if (!every && !callback.is_none()) callback(self);
  }

  void save() {
    usable();
    const ThreadCount count(threads_);
    run_->write_checkpoint();
  }

 private:
  // Sets a flag while it lives.
  class Raised {
   public:
    explicit Raised(bool& flag) : flag_(flag) { flag_ = true; }
    ~Raised() { flag_ = false; }
    Raised(const Raised&) = delete;
    Raised& operator=(const Raised&) = delete;

   private:
    bool& flag_;
  };
  // Not stepping: another Python thread, while the step runs without the GIL, may neither read
  // the simulation nor step it.
  void idle() const {
    if (stepping_) throw std::runtime_error("the simulation is stepping: wait for its step to end");
  }
  // Neither stepping nor in a controller, which may read the simulation but not step, save or
  // drive it.
  void not_within_a_step() const {
    idle();
    if (controlling_) {
      throw std::runtime_error("a controller may read the simulation, not step, save or drive it");
    }
  }
  // Not within a step, and not diverged: a run that went wrong is of no further use.
  void usable() const {
    not_within_a_step();
    if (diverged_) {
      throw std::runtime_error(
          "the run diverged: its last good state is the last frame written; start a new "
          "Simulation");
    }
  }
  // The controllers' velocities (over a copy of the list: a controller may drive a body),
  // then a step without the GIL.
  void one_step(const py::object& self, double until) {
    if (!controllers_.empty()) {
      const Raised controlling(controlling_);
      const auto start = std::chrono::steady_clock::now();
      const auto controllers = controllers_;
      for (const auto& [b, controller] : controllers) {
        const auto [velocity, angular_velocity] = commanded(controller(self));
        run_->command_velocity(b, velocity, angular_velocity);
      }
      controller_seconds_ +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    const ThreadCount count(threads_);
    const Raised stepping(stepping_);
    const py::gil_scoped_release free_python;
    try {
      run_->step(until);
    } catch (const DivergenceError&) {
      diverged_ = true;
      throw;
    }
  }
  // A controller's answer: a velocity, or (velocity, angular velocity); 3 components each, or
  // for a 2D case's velocity 2 (x, z).
  std::pair<Vec3, Vec3> commanded(const py::object& answer) const {
    const auto vector = [&](const py::handle& h, bool plane) {
      const auto values = py::cast<std::vector<double>>(h);
      if (values.size() == 3) return Vec3(values[0], values[1], values[2]);
      if (values.size() == 2 && plane) return Vec3(values[0], 0, values[1]);
      throw py::value_error(
          "a controller gives a velocity of 3 components (2 in 2D: x, z), or "
          "a pair (velocity, angular velocity of 3 components)");
    };
    const bool pair = PySequence_Check(answer.ptr()) == 1 && py::len(answer) == 2 &&
                      PySequence_Check(answer[py::int_(0)].ptr()) == 1;
    const bool plane = run_->dimension() == 2;
    if (pair) return {vector(answer[py::int_(0)], plane), vector(answer[py::int_(1)], false)};
    return {vector(answer, plane), Vec3::Zero()};
  }
  std::size_t body_index(const std::string& name) const {
    const auto& bodies = run_->config().bodies;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      if (bodies[b].name == name) return b;
    }
    throw py::key_error("no body named '" + name + "'");
  }
  void check_until(double until) const {
    if (!(until > time() + 1e-12 * std::max(1.0, until))) {
      throw py::value_error("until (" + std::to_string(until) +
                            " s) must lie after the simulation's time (" + std::to_string(time()) +
                            " s)");
    }
    if (until > run_->end_time() * (1 + 1e-12)) {
      throw py::value_error("until is past the run's end time (" +
                            std::to_string(run_->end_time()) +
                            " s): give the Simulation a later end");
    }
  }

  int threads_;
  std::unique_ptr<CaseRun> run_;
  std::vector<std::pair<std::size_t, py::object>> controllers_;  // body, controller(sim)
  double controller_seconds_ = 0;                                // spent in the controllers
  bool stepping_ = false, controlling_ = false, diverged_ = false;
};

py::dict bodies_of(const CaseRun& run) {
  py::dict out;
  const RigidBodies& bodies = run.bodies();
  const auto& force = run.coupler().fluid_force();
  const auto& moment = run.coupler().fluid_moment();
  const auto& contact_force = bodies.system().contact_force();
  const auto& contact_moment = bodies.system().contact_torque();
  for (std::size_t b = 0; b < bodies.count(); ++b) {
    const RigidBody& s = bodies.state(b);
    const Eigen::Quaterniond q = bodies.shape_orientation(b);
    py::dict body;
    body["position"] = vector_array(s.position);
    body["orientation"] = vector_array(Vec3(q.x(), q.y(), q.z()), q.w());
    body["velocity"] = vector_array(s.velocity);
    body["angular_velocity"] = vector_array(s.inverse_world_inertia() * s.angular_momentum);
    body["fluid_force"] = vector_array(b < force.size() ? force[b] : Vec3::Zero());
    body["fluid_moment"] = vector_array(b < moment.size() ? moment[b] : Vec3::Zero());
    body["contact_force"] = vector_array(contact_force[b]);
    body["contact_moment"] = vector_array(contact_moment[b]);
    body["mass"] = s.mass;
    out[py::str(bodies.config(b).name)] = body;
  }
  return out;
}

py::dict summary_of(const RunSummary& r) {
  py::dict out;
  out["steps"] = r.steps;
  out["simulated_time"] = r.simulated_time;
  out["wall_seconds"] = r.wall_seconds;
  out["particles"] = r.particles;
  out["fluid_particles"] = r.fluid_particles;
  out["particle_steps_per_second"] = r.particle_steps_per_second();
  out["threads"] = r.threads;
  out["frames"] = r.frames;
  out["checkpoints"] = r.checkpoints;
  py::dict stages;
  for (const auto& e : r.stages) stages[py::str(e.name)] = e.seconds;
  out["stage_seconds"] = stages;
  return out;
}

}  // namespace

void bind_simulation(py::module_& m) {
  py::register_exception<DivergenceError>(m, "DivergenceError", PyExc_RuntimeError)
      .attr("__doc__") =
      "The run went wrong (non-finite values, water or a body out of the domain, a step that "
      "collapsed); the last good state is the last frame written. The simulation is of no "
      "further use.";
  py::class_<Simulation>(m, "Simulation", R"doc(
A case's run, stepped from Python. It writes what `sluice run` writes (frames, probes.csv, the
bodies' files, checkpoints) into `out` (default out/CASE_NAME) on the case's schedule.

    sim = sluice.Simulation(case, threads=2)
    sim.run(until=0.5, every=0.1, callback=lambda s: print(s.time, s.probes()))

`threads` is this simulation's thread count (0: every core), set while it steps and put back
after. `device` ('cpu', 'gpu', 'emulated'; default: the case's model.device) is where its loops
run, as `sluice run --device`. `end` overrides the case's end_time; `resume=True` goes on from the newest checkpoint in
`out` (Simulation.resume). Bad input raises sluice.InputError, a run gone wrong
sluice.DivergenceError.)doc")
      .def(py::init<const io::CaseConfig&, std::optional<std::string>, int, std::optional<double>,
                    bool, bool, std::optional<std::string>>(),
           py::arg("case"), py::arg("out") = py::none(), py::arg("threads") = 0,
           py::arg("end") = py::none(), py::arg("resume") = false, py::arg("progress") = false,
           py::arg("device") = py::none())
      .def_static(
          "resume",
          [](const io::CaseConfig& config, const std::string& out, int threads,
             std::optional<double> end) {
            return std::make_unique<Simulation>(config, out, threads, end, true, false);
          },
          py::arg("case"), py::arg("out"), py::arg("threads") = 0, py::arg("end") = py::none(),
          "Goes on with `case` from the newest checkpoint in `out` (InputError when none fits "
          "the case).")
      .def_property_readonly("time", &Simulation::time, "The simulated time [s].")
      .def_property_readonly("steps", &Simulation::steps, "Steps from the case's start.")
      .def_property_readonly("threads", &Simulation::threads)
      .def_property_readonly("end_time", [](const Simulation& s) { return s.run().end_time(); })
      .def_property_readonly("out", [](const Simulation& s) { return s.run().out_dir(); })
      .def_property_readonly("dimension", [](const Simulation& s) { return s.run().dimension(); })
      .def(
          "step",
          [](py::object self, std::optional<double> until) {
            self.cast<Simulation&>().step(self, until);
          },
          py::arg("until") = py::none(),
          "One step of the model's stable size, landing on the next output time and not past "
          "`until` (default: the end time).")
      .def("drive", &Simulation::drive, py::arg("body"), py::arg("controller"), R"doc(
Drives prescribed body `body` from Python: before every step, controller(sim) gives its velocity
(of its centre of mass) as 3 numbers (2 in 2D: x, z), or a pair (velocity, angular velocity
[rad/s]); the body moves on from where it stands at that velocity over the step, in place of the
case's motion. None stops calling it (the body keeps its last velocity). KeyError for an unknown
body, ValueError for one whose motion is not prescribed. summary()['controller_seconds'] is the
time spent in the controllers.)doc")
      .def(
          "run",
          [](py::object self, std::optional<double> until, std::optional<double> every,
             const py::object& callback) {
            self.cast<Simulation&>().run_to(self, until, every, callback);
          },
          py::arg("until") = py::none(), py::arg("every") = py::none(),
          py::arg("callback") = py::none(),
          "Steps to `until` (default: the end time). With `every` [simulated s], calls "
          "callback(sim) at each multiple of it; without, once at the end where one is given. "
          "An exception the callback raises stops the run there and propagates; the simulation "
          "stays at its last whole step and can go on.")
      .def("save", &Simulation::save,
           "Writes a checkpoint now into OUT/checkpoints (Simulation.resume reads it).")
      .def(
          "fields",
          [](py::object self, bool copy) {
            return fields_of(self.cast<Simulation&>().run().fluid().view(), self, copy);
          },
          py::arg("copy") = false, R"doc(
The fluid's fields at its points (particles; a grid model's free surface) as numpy arrays, by
name, 'position' among them: (n,) or (n, components); a 2D case's vectors hold (x, z).
Without copy they view the model's own arrays, read-only, and hold only until the next step:
the cell sort reorders the particles and the arrays may move. Keep `copy=True` ones.)doc")
      .def(
          "grid_fields",
          [](py::object self, bool copy) {
            return grid_fields_of(self.cast<Simulation&>().run().fluid().view(), self, copy);
          },
          py::arg("copy") = false,
          "A grid model's (mac) cell fields as arrays shaped (nz, ny, nx[, components]), with "
          "'origin' and 'spacing'; None for a particle model.")
      .def(
          "probes",
          [](const Simulation& s) {
            py::dict out;
            const auto labels = s.run().probe_labels();
            const auto values = s.run().probe_values();
            for (std::size_t k = 0; k < labels.size(); ++k) out[py::str(labels[k])] = values[k];
            return out;
          },
          "Each probe's reading now, by its probes.csv label ('P1 [Pa]').")
      .def(
          "probe_record",
          [](const Simulation& s) {
            const auto& rows = s.run().probe_record();
            std::vector<std::string> labels{"time [s]"};
            for (const std::string& label : s.run().probe_labels()) labels.push_back(label);
            py::dict out;
            for (std::size_t k = 0; k < labels.size(); ++k) {
              py::array_t<double> column(static_cast<py::ssize_t>(rows.size()));
              auto values = column.mutable_unchecked<1>();
              for (std::size_t r = 0; r < rows.size(); ++r) {
                values(static_cast<py::ssize_t>(r)) = rows[r][k];
              }
              out[py::str(labels[k])] = column;
            }
            return out;
          },
          "The probes as probes.csv records them, on the case's probe_interval, since this "
          "simulation began (a resumed one: since its checkpoint): numpy arrays by label, "
          "'time [s]' first, then each probe's ('P1 [Pa]', 'front [m]'); copies.")
      .def(
          "bodies", [](const Simulation& s) { return bodies_of(s.run()); },
          "Each body by name: position (its centre of mass), orientation (x, y, z, w), velocity, "
          "angular_velocity, the fluid's force and moment (about the centre of mass) as held "
          "over the last step, the contacts' force and moment (other bodies' and the walls') "
          "at the last solid sub-step, and mass; vectors in 3D (a 2D case's y is 0).")
      .def(
          "summary",
          [](const Simulation& s) {
            py::dict out = summary_of(s.run().summary());
            out["controller_seconds"] = s.controller_seconds();
            return out;
          },
          "What the run did so far: steps, wall seconds, particle-steps per second and the "
          "stages' seconds, as --stats writes them.")
      .def("__repr__", [](const Simulation& s) {
        return "<sluice.Simulation '" + s.run().config().name +
               "' at t = " + std::to_string(s.time()) + " s, step " + std::to_string(s.steps()) +
               ">";
      });
}

}  // namespace sluice::python
