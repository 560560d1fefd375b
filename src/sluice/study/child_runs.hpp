// Runs of `sluice run` started by a sweep and a comparison (sweep.hpp, compare.hpp): each a child
// process with its messages in a log file, several at once where the cores allow.
#pragma once

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace sluice {

class HypreSession;  // linear/hypre_session.hpp

// What a sweep and a comparison share: the case, the settings of every run, where they go.
struct StudyOptions {
  std::string case_path;
  std::vector<std::string> settings;  // --set arguments (a sweep's axes among them)
  std::string out_dir;                // default: out/sweep_CASE_NAME, out/compare_CASE_NAME
  int jobs = 0;                       // runs at once; 0: the study's default
  double end_time = 0;                // 0 = the case's
  std::string program;                // the sluice executable, which runs each case
  HypreSession* hypre = nullptr;      // the process's, for the checks (sim/runner.hpp)
  bool report = true;  // lines on stdout: the study's start, each run's end, the table, the plots
  // Called once every run's case has been checked (the checks may solve with hypre), before
  // anything runs or is written: where Python lets its other threads go on.
  std::function<void()> checked;
  // Asked every 20 ms while the runs go on: true stops them (StudyStopped). Python's Ctrl-C.
  std::function<bool()> stop_requested;
};

// Creates the study's output directory; InputError naming it when it cannot.
void create_study_directory(const std::string& dir);

// With options.report, "HEAD (J at once, T threads each) in OUT" on stdout.
void report_study_start(const StudyOptions& options, const std::string& head, int jobs, int threads,
                        const std::string& out_dir);

// With options.report, "[N/TOTAL] LABEL: STATUS in S s" on stdout, naming the run's log where
// it did not finish.
void report_run_end(const StudyOptions& options, std::size_t finished, std::size_t total,
                    const std::string& label, const std::string& status, double seconds,
                    const std::string& run_dir);

struct ChildRun {
  std::vector<std::string> args;  // args[0] is the program
  std::string log;                // its stdout and stderr go here
};

struct ChildOutcome {
  std::string status;  // "done", "diverged", "failed (exit N)", "failed (killed)"
  double seconds = 0;  // wall-clock
};

// `PROGRAM run CASE --out DIR --threads N --stats DIR/stats.json [--end T] --set ...`, its
// messages in DIR.log. end_time 0: the case's.
ChildRun sluice_run(const std::string& program, const std::string& case_path,
                    const std::string& dir, int threads, double end_time,
                    const std::vector<std::string>& overrides);

// Thrown by run_children when its caller asks it to stop (Ctrl-C in a Python script).
struct StudyStopped : std::runtime_error {
  StudyStopped() : std::runtime_error("the study was stopped") {}
};

// Runs `runs`, `jobs` at once, and calls `finished(k, outcome)` as run k ends, asking
// `stop_requested` (where given) every 20 ms whether to stop: then StudyStopped. Throws
// std::runtime_error when a run cannot be started. Whatever it throws, the runs still going
// are stopped (SIGTERM) and waited for first.
std::vector<ChildOutcome> run_children(
    const std::vector<ChildRun>& runs, int jobs,
    const std::function<void(std::size_t, const ChildOutcome&)>& finished,
    const std::function<bool()>& stop_requested = {});

// The threads each of `jobs` runs at once gets: the cores shared out, at least one.
int threads_per_run(int jobs);

// This program's path, to start the runs with.
std::string this_program();

// Runs `/usr/bin/python3 SLUICE_SOURCE_DIR/scripts/SCRIPT ARGS...` (Debian's matplotlib) and
// waits for it: its exit code, or nothing where python3 or the script is missing or it did not
// exit. With `log`, its stdout and stderr go to that file.
std::optional<int> run_script(const std::string& script, const std::vector<std::string>& args,
                              const std::string& log = "");

// run_script, with `report` saying so on stdout when it could not run or failed: plots that a
// run's table does without.
void draw_plots(const std::string& script, const std::vector<std::string>& args, bool report);

}  // namespace sluice
